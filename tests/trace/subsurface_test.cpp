// Subsurface light transport's numbers against values derived from POV-Ray 3.7's formulas
// (docs/subsurface.md): the diffuse Fresnel reflectance, the reduced-albedo table, the
// two sample tables and the dipole.
#include "trace/subsurface.h"

#include <gtest/gtest.h>

namespace povwall::trace::subsurface {
namespace {

TEST(Subsurface, DiffuseFresnelReflectance) {
    EXPECT_DOUBLE_EQ(diffuse_fresnel_reflectance(1.0), 0.0);
    EXPECT_NEAR(diffuse_fresnel_reflectance(1.3), 0.058714098, 1e-9);
    EXPECT_NEAR(diffuse_fresnel_reflectance(1.45), 0.081462009, 1e-9);
    EXPECT_NEAR(diffuse_fresnel_reflectance(1.5), 0.088679169, 1e-9);
    // Below 1: eta^2 - eta^2.25.
    EXPECT_NEAR(diffuse_fresnel_reflectance(0.5), 0.25 - 0.2102241038, 1e-9);
}

TEST(Subsurface, ReducedAlbedoTable) {
    const AlbedoTable t13(1.3), t15(1.5), t10(1.0);
    EXPECT_EQ(t13.entry(0), 0.0f);
    EXPECT_EQ(t13.entry(100), 1.0f);
    EXPECT_NEAR(t13.reduced_albedo(0.5), 0.9491786, 5e-7);
    EXPECT_NEAR(t13.reduced_albedo(0.72), 0.9883888, 5e-7);
    EXPECT_NEAR(t13.reduced_albedo(0.05), 0.3567331, 5e-7);
    EXPECT_NEAR(t13.reduced_albedo(0.25), 0.8082680, 5e-7);
    EXPECT_NEAR(t15.reduced_albedo(0.008), 0.0773714, 5e-7);
    EXPECT_NEAR(t15.reduced_albedo(0.664), 0.9827643, 5e-7);
    EXPECT_NEAR(t10.reduced_albedo(0.9), 0.9986790, 5e-7);
    // Outside [0, 1] the table is read at its ends.
    EXPECT_EQ(t13.reduced_albedo(1.7), 1.0);
    EXPECT_EQ(t13.reduced_albedo(-0.2), 0.0);
}

TEST(Subsurface, SampleTablesAreMt19937AndHalton) {
    const double u[] = {0.8147236919, 0.1354770041, 0.9057919341,
                        0.8350085898, 0.1269868119, 0.9688677711};
    for (size_t k = 0; k < 6; ++k) EXPECT_NEAR(uniform_number(k), u[k], 1e-10) << k;
    const double d[][3] = {{0, -0.5, 0.866025404},
                           {-0.5, -0.433012702, -0.75},
                           {0.5, 0.663413948, 0.556670399},
                           {-0.75, -0.621548246, 0.226225061},
                           {0.25, 0.168134125, -0.953536007}};
    for (size_t k = 0; k < 5; ++k) {
        const Vector3& v = sphere_direction(k);
        EXPECT_NEAR(v.x, d[k][0], 1e-9) << k;
        EXPECT_NEAR(v.y, d[k][1], 1e-9) << k;
        EXPECT_NEAR(v.z, d[k][2], 1e-9) << k;
    }
    // The tables wrap.
    EXPECT_EQ(uniform_number(kTableSize + 2), uniform_number(2));
}

TEST(Subsurface, DipoleAndTransmittance) {
    // translucency 1.2 mm, reflectance 0.72, relative index 1.3.
    const double albedo = AlbedoTable(1.3).reduced_albedo(0.72);
    const double scattering = 1 / 1.2, extinction = scattering / albedo;
    const double absorption = extinction - scattering;
    EXPECT_NEAR(extinction, 0.843123, 1e-6);
    EXPECT_NEAR(absorption, 0.009790, 1e-6);
    const double fdr = diffuse_fresnel_reflectance(1.3);
    const double a = (1 + fdr) / (1 - fdr);
    const double alpha = scattering / extinction;
    EXPECT_NEAR(dipole_reflectance(extinction, absorption, alpha, a, 0), 6.32808816e-2,
                1e-8);
    EXPECT_NEAR(dipole_reflectance(extinction, absorption, alpha, a, 0.25), 5.08358983e-2,
                1e-8);
    EXPECT_NEAR(dipole_reflectance(extinction, absorption, alpha, a, 4), 1.15679876e-2,
                1e-8);
    EXPECT_NEAR(fresnel_transmittance(1, 1.3), 0.9829868, 1e-7);
    EXPECT_NEAR(fresnel_transmittance(0.5, 1.3), 0.9466005, 1e-7);
    // Past the critical angle (eta < 1) and off [-1, 1]: POV-Ray's NaN clamps to 1.
    EXPECT_EQ(fresnel_transmittance(0.1, 0.7), 1.0);
    EXPECT_EQ(fresnel_transmittance(1.0000001, 1.3), 1.0);
}

}  // namespace
}  // namespace povwall::trace::subsurface
