// POV-Ray 3.7's degree-to-radian constants (its M_PI_180 and M_PI_360). POV-Ray
// multiplies an angle in degrees by one of them; computing `degrees * pi / 180` instead
// rounds differently for some angles (46 or 59 degrees: the last bit). Where the result
// sets a camera ray, one bit is enough to flip which grazing rays POV-Ray's
// ill-conditioned root solvers report as hits (a sor seen edge-on), so the camera set-up
// uses these.
#pragma once

namespace povwall {

constexpr double kPovRadiansPerDegree = 0.01745329251994329576;      // M_PI_180
constexpr double kPovRadiansPerHalfDegree = 0.00872664625997164788;  // M_PI_360

}  // namespace povwall
