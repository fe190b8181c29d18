#include "trace/mesh_camera.h"

#include <algorithm>
#include <cstdint>

#include "core/math_constants.h"

namespace povwall::trace {
namespace {

// C's conversion of a double to unsigned int as POV-Ray's indices take it (toward zero;
// a small negative value gives 0).
uint32_t as_index(double v) { return uint32_t(int64_t(v)); }

Point3 centroid(const MeshCamera::Face& f) {
    return Point3{(f.p[0].x + f.p[1].x + f.p[2].x) / 3,
                  (f.p[0].y + f.p[1].y + f.p[2].y) / 3,
                  (f.p[0].z + f.p[1].z + f.p[2].z) / 3};
}

// POV-Ray's Smooth_Mesh_Normal: the vertex normals interpolated over the face from
// the first corner (its own normal right at it), not unit.
Vector3 smooth_normal(const MeshCamera::Face& f, const Point3& at) {
    if (!f.smooth) return f.normal;
    const Vector3 d = at - f.p[0];
    const Real u = dot(d, f.perp);
    if (u < kPovEpsilon) return f.n[0];
    auto axis = [&](const Vector3& v) {
        return f.v_axis == 0 ? v.x : f.v_axis == 1 ? v.y : v.z;
    };
    const Real k1 = axis(f.p[0] - Point3{0, 0, 0}), k2 = axis(f.p[1] - Point3{0, 0, 0}),
               k3 = axis(f.p[2] - Point3{0, 0, 0});
    const Real v = (axis(d) / u + k1 - k2) / (k3 - k2);
    return f.n[0] + (f.n[1] - f.n[0] + (f.n[2] - f.n[1]) * v) * u;
}

// Distribution 3: the first face of the first mesh whose uv triangle holds (u, v), and
// the point there (barycentric weights from the uv coordinates).
const MeshCamera::Face* face_at_uv(const MeshCamera& mc, double u, double v, Point3& at) {
    const MeshCamera::Part& mesh = mc.meshes[0];
    const auto& us = mc.u_faces[std::min(as_index(u * 10), 9u)];
    const auto& vs = mc.v_faces[std::min(as_index(v * 10), 9u)];
    for (size_t idx = 0; idx < us.size(); ++idx) {
        const uint32_t both = us[idx] & vs[idx];
        if (both == 0) continue;
        for (uint32_t bit = 0; bit < 32; ++bit) {
            if (!(both & (uint32_t(1) << bit))) continue;
            const MeshCamera::Face& f = mesh.faces[idx * 32 + bit];
            const double scale = (f.u[1] - f.u[0]) * (f.v[2] - f.v[0]) -
                                 (f.u[2] - f.u[0]) * (f.v[1] - f.v[0]);
            const double b1 =
                ((f.u[1] - u) * (f.v[2] - v) - (f.u[2] - u) * (f.v[1] - v)) / scale;
            const double b2 =
                ((f.u[2] - u) * (f.v[0] - v) - (f.u[0] - u) * (f.v[2] - v)) / scale;
            const double b3 =
                ((f.u[0] - u) * (f.v[1] - v) - (f.u[1] - u) * (f.v[0] - v)) / scale;
            // POV-Ray's test: NaN weights (a face without uv area) pass.
            if (b1 < 0 || b2 < 0 || b3 < 0) continue;
            at = Point3{f.p[0].x * b1 + f.p[1].x * b2 + f.p[2].x * b3,
                        f.p[0].y * b1 + f.p[1].y * b2 + f.p[2].y * b3,
                        f.p[0].z * b1 + f.p[1].z * b2 + f.p[2].z * b3};
            return &f;
        }
    }
    return nullptr;
}

}  // namespace

std::optional<Ray> mesh_camera_ray(const MeshCamera& mc, const Camera& camera,
                                   Real shifted_x, Real shifted_y, int width, int height,
                                   int ray) {
    // POV-Ray clips the position to the image (its rows 0 and 1 both reach row 0: the
    // shift to the pixel centre moves y up by one half).
    const double x = std::max(0.0, std::min(double(shifted_x), width - 1.0));
    const double y = std::max(0.0, std::min(double(shifted_y), height - 1.0));
    const MeshCamera::Part* mesh = nullptr;
    const MeshCamera::Face* face = nullptr;
    Point3 origin;
    Vector3 dir;
    const uint32_t pixel = as_index(y) * uint32_t(width) + as_index(x);
    switch (mc.distribution) {
        case 0: {
            mesh = &mc.meshes[size_t(ray)];
            if (pixel >= mesh->faces.size()) return std::nullopt;
            face = &mesh->faces[pixel];
            break;
        }
        case 1: {
            // POV-Ray adds ray * (all faces), so only ray 0 ever finds a face.
            const uint64_t index = uint64_t(pixel) + uint64_t(ray) * mc.face_ends.back();
            if (index >= mc.face_ends.back()) return std::nullopt;
            uint32_t first = 0;
            for (size_t m = 0; m < mc.face_ends.size(); first = mc.face_ends[m++]) {
                if (mc.face_ends[m] > index) {
                    mesh = &mc.meshes[m];
                    face = &mesh->faces[size_t(index - first)];
                    break;
                }
            }
            if (!face) return std::nullopt;
            break;
        }
        case 2: {
            // Side by side; the face index counts x from the image's left edge, as
            // POV-Ray's does.
            const size_t n = mc.meshes.size();
            const size_t m = size_t(x / (double(width) / double(n)));
            mesh = &mc.meshes[std::min(m, n - 1)];
            const uint32_t index =
                as_index(y) * uint32_t(uint32_t(width) / n) + as_index(x);
            if (index >= mesh->faces.size()) return std::nullopt;
            face = &mesh->faces[index];
            break;
        }
        default: {
            mesh = &mc.meshes[0];
            face = face_at_uv(mc, (x - 0.5) / width, 1.0 - (y + 0.5) / height, origin);
            if (!face) return std::nullopt;
            dir = mc.smooth ? smooth_normal(*face, origin) : face->normal;
            break;
        }
    }
    if (mc.distribution != 3) {
        origin = centroid(*face);
        dir = face->normal;
    }
    origin = origin + dir * camera.location.z;
    if (camera.direction.z < -kPovEpsilon) dir = dir * -1.0;
    if (!mesh->transform.is_identity()) {
        origin = mesh->transform.point(origin);
        dir = mesh->transform.normal(dir);
    }
    return Ray{origin, dir};
}

}  // namespace povwall::trace
