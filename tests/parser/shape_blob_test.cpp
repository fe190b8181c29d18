// blob as POV-Ray 3.7 parses it: the element order (reversed, cylinders expanded), the
// field coefficients, component transforms (a sphere moved in place or made an
// ellipsoid), the cylinder's frame, threshold, sturm, hierarchy and the errors.
#include <gtest/gtest.h>

#include "tests/parser/parse_helpers.h"

namespace povwall::parser {
namespace {

using test::error_of;
using test::only_shape;
using test::parse;

TEST(ShapeBlob, ElementsReversedWithTheirCoefficients) {
    auto b = only_shape<Blob>(parse(
        "blob { sphere { <1, 2, 3>, 2, 4 } threshold 0.25 component 3 0.5 <0, 1, 0> "
        "sphere { 0, 1, strength -1 } sturm }"));
    const BlobData& d = *b.data;
    EXPECT_EQ(d.threshold, 0.25);
    EXPECT_TRUE(b.sturm);
    EXPECT_TRUE(b.hierarchy);
    ASSERT_EQ(d.elements.size(), 3u);
    // The last component comes first.
    EXPECT_EQ(d.elements[0].c[2], -1.0);
    EXPECT_EQ(d.elements[1].c[2], 3.0);
    EXPECT_EQ(d.elements[1].rad2, 0.25);
    EXPECT_EQ(d.elements[1].origin.y, 1.0);
    const BlobElement& e = d.elements[2];
    EXPECT_EQ(e.kind, BlobElementKind::Sphere);
    EXPECT_EQ(e.origin.z, 3.0);
    EXPECT_EQ(e.rad2, 4.0);
    // s (1 - r^2/R^2)^2 = s/R^4 r^4 - 2s/R^2 r^2 + s.
    EXPECT_EQ(e.c[0], 0.25);
    EXPECT_EQ(e.c[1], -2.0);
    EXPECT_EQ(e.c[2], 4.0);
    EXPECT_EQ(only_shape<Blob>(parse("blob { sphere { 0, 1, 1 } }")).data->threshold,
              1.0);
    EXPECT_FALSE(
        only_shape<Blob>(parse("blob { sphere { 0, 1, 1 } hierarchy off }")).hierarchy);
}

TEST(ShapeBlob, CylinderBodyThenHemispheresInItsFrame) {
    auto b =
        only_shape<Blob>(parse("blob { cylinder { <1, 0, 0>, <1, 3, 0>, 0.5, 2 } }"));
    const BlobData& d = *b.data;
    ASSERT_EQ(d.elements.size(), 3u);
    EXPECT_EQ(d.elements[0].kind, BlobElementKind::Cylinder);
    EXPECT_EQ(d.elements[1].kind, BlobElementKind::BaseHemisphere);
    EXPECT_EQ(d.elements[2].kind, BlobElementKind::ApexHemisphere);
    for (const BlobElement& e : d.elements) {
        EXPECT_EQ(e.len, 3.0);
        EXPECT_EQ(e.rad2, 0.25);
        EXPECT_EQ(e.c[0], 32.0);
        EXPECT_EQ(e.c[1], -16.0);
    }
    // z of the frame runs from the base to the apex.
    const Point3 apex = d.elements[0].transform.point({0, 0, 3});
    EXPECT_NEAR(apex.x, 1.0, 1e-15);
    EXPECT_NEAR(apex.y, 3.0, 1e-15);
    EXPECT_NEAR(apex.z, 0.0, 1e-15);
    const Point3 base = d.elements[0].transform.inverse_point({1, 0, 0});
    EXPECT_NEAR(base.z, 0.0, 1e-15);
}

TEST(ShapeBlob, SphereComponentTransforms) {
    // translate, rotate and a uniform scale move the centre and the radius in place.
    auto b = only_shape<Blob>(
        parse("blob { sphere { <1, 0, 0>, 1, 1 translate y scale 2 rotate 90*z } }"));
    const BlobElement& e = b.data->elements[0];
    EXPECT_EQ(e.kind, BlobElementKind::Sphere);
    EXPECT_EQ(e.rad2, 4.0);
    EXPECT_NEAR(e.origin.x, -2.0, 1e-15);
    EXPECT_NEAR(e.origin.y, 2.0, 1e-15);
    // A non-uniform scale makes it an ellipsoid with the steps after it in its matrix.
    b = only_shape<Blob>(
        parse("blob { sphere { <1, 0, 0>, 1, 1 translate y scale <2, 1, 1> translate z } "
              "}"));
    const BlobElement& el = b.data->elements[0];
    EXPECT_EQ(el.kind, BlobElementKind::Ellipsoid);
    EXPECT_EQ(el.origin.y, 1.0);
    EXPECT_EQ(el.rad2, 1.0);
    const Point3 p = el.transform.point({1, 1, 0});
    EXPECT_EQ(p.x, 2.0);
    EXPECT_EQ(p.z, 1.0);
    // The object's own transforms leave the elements alone.
    Scene s = parse("blob { sphere { 0, 1, 1 } translate x }");
    EXPECT_EQ(std::get<Blob>(s.objects[0].shape).data->elements[0].origin.x, 0.0);
    EXPECT_EQ(s.objects[0].transform.point({0, 0, 0}).x, 1.0);
}

TEST(ShapeBlob, ComponentTexturesPerElementMovedByTransforms) {
    Scene sc = parse(
        "blob { sphere { 0, 1, 1 pigment { rgb x } translate y } "
        "cylinder { 0, x, 0.5, 1 } sphere { 0, 1, 1 texture { pigment { rgb z } } } "
        "translate 2*x }");
    const Blob& b = std::get<Blob>(sc.objects[0].shape);
    ASSERT_EQ(b.data->elements.size(), 5u);
    ASSERT_EQ(b.element_textures.size(), 5u);
    // Reversed: the last sphere, the cylinder's three elements, the first sphere.
    EXPECT_EQ(b.element_textures[0].front().pigment.colour.rgb.b, 1.0f);
    for (int k = 1; k <= 3; ++k) EXPECT_TRUE(b.element_textures[size_t(k)].empty());
    const Texture& first = b.element_textures[4].front();
    EXPECT_EQ(first.pigment.colour.rgb.r, 1.0f);
    // Moved by its component's translate and by the blob's.
    const Point3 o = first.pigment.pattern->transform.point({0, 0, 0});
    EXPECT_EQ(o.x, 2.0);
    EXPECT_EQ(o.y, 1.0);
    // No component texture: no list.
    EXPECT_TRUE(only_shape<Blob>(parse("blob { sphere { 0, 1, 1 } pigment { rgb 1 } }"))
                    .element_textures.empty());
}

TEST(ShapeBlob, Errors) {
    EXPECT_EQ(error_of("blob { threshold 1 }"),
              "test.pov:1:20: error: Need at least one component in a blob.");
    EXPECT_EQ(error_of("blob { cylinder { 1, 1, 1, 1 } }"),
              "test.pov:1:8: error: Degenerate cylindrical component in blob.");
    EXPECT_EQ(error_of("blob { sphere { 0, 1, 1 open } }"),
              "test.pov:1:25: error: expected a blob component modifier or '}' but found "
              "'open'");
    EXPECT_EQ(error_of("sphere { 0, 1 hierarchy }"),
              "test.pov:1:15: error: 'hierarchy' cannot be used with this object");
}

}  // namespace
}  // namespace povwall::parser
