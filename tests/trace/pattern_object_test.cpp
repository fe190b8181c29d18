// The object pattern compared value for value with POV-Ray 3.7's render of the same
// pigment on a plane (ambient only): inside a transformed sphere, a difference, an
// inverse box; colour entries and the default (checker's) colours.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "tests/trace/pov_reference.h"
#include "trace/pattern.h"

namespace povwall::trace {
namespace {

constexpr int kPatternObjectImageSize = 16;

double max_error(const std::string& pov_pigment, const Pigment& pigment,
                 const test::TopView& view) {
    const std::string scene = "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n" +
                              view.camera() + "plane { y, " +
                              std::to_string(view.height) + " pigment { " + pov_pigment +
                              " } finish { ambient 1 diffuse 0 } }\n";
    const test::RgbImage img = test::render_with_povray(scene, kPatternObjectImageSize);
    double worst = 0;
    for (int y = 0; y < kPatternObjectImageSize; ++y) {
        for (int x = 0; x < kPatternObjectImageSize; ++x) {
            const Colour c =
                evaluate_pigment(pigment, view.point(x, y, kPatternObjectImageSize), {});
            const float mine[3] = {c.rgb.r, c.rgb.g, c.rgb.b};
            for (int ch = 0; ch < 3; ++ch)
                worst = std::max(
                    worst,
                    std::fabs(img.at(x, y, ch) - std::clamp(double(mine[ch]), 0.0, 1.0)));
        }
    }
    std::printf("max error %.2e  pigment { %s }\n", worst, pov_pigment.c_str());
    return worst;
}

Object sphere(Point3 centre, Real radius) {
    Object o;
    o.shape = Sphere{centre, radius};
    return o;
}

Pigment object_pigment(Object o, bool colours) {
    Pigment p;
    p.pattern.edit().kind = PatternKind::ObjectInside;
    p.pattern.edit().frequency = 0;  // as parsed
    p.pattern.edit().object = std::make_shared<const Object>(std::move(o));
    if (colours) {
        Pigment out, in;
        out.colour = Colour{Rgb{0.2f, 0.4f, 0.6f}};
        in.colour = Colour{Rgb{0.9f, 0.1f, 0.3f}};
        p.maps.edit().list = {out, in};
    }
    return p;
}

TEST(ObjectPatternVsPovray, InsideTests) {
    test::TopView view;
    view.extent = 5;
    // A scaled sphere, default colours.
    Object s = sphere({0.5, 0, 0}, 1);
    s.transform = Transform::scale({1.5, 1, 0.7});
    EXPECT_LE(max_error("object { sphere { <0.5, 0, 0>, 1 scale <1.5, 1, 0.7> } }",
                        object_pigment(s, false), view),
              1e-3);
    // A difference, with colour entries, the pattern itself turned.
    Object d;
    Csg csg;
    csg.kind = CsgKind::Difference;
    csg.children.push_back(sphere({0, 0, 0}, 1.8));
    csg.children.push_back(sphere({0.6, 0, 0.3}, 0.9));
    d.shape = std::move(csg);
    Pigment p = object_pigment(std::move(d), true);
    p.pattern.edit().transform = Transform::rotate({0, 30, 0});
    EXPECT_LE(
        max_error("object { difference { sphere { 0, 1.8 } sphere { <0.6, 0, 0.3>, "
                  "0.9 } } rgb <0.2, 0.4, 0.6>, rgb <0.9, 0.1, 0.3> } rotate 30 * y",
                  p, view),
        1e-3);
    // An inverse box.
    Object b;
    b.shape = Box{{-1, -1, -1}, {1.2, 1, 0.8}};
    b.inverse = true;
    EXPECT_LE(max_error("object { box { <-1, -1, -1>, <1.2, 1, 0.8> inverse } rgb "
                        "<0.2, 0.4, 0.6>, rgb <0.9, 0.1, 0.3> }",
                        object_pigment(std::move(b), true), view),
              1e-3);
}

}  // namespace
}  // namespace povwall::trace
