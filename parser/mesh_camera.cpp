// camera { mesh_camera { } } (POV-Ray 3.7's Parse_Mesh_Camera): the meshes whose faces
// start the camera rays, kept in mesh space with their transforms (core/mesh_camera.h).
#include "core/mesh_camera.h"

#include <algorithm>
#include <cmath>

#include "parser/interpreter.h"

namespace povwall::parser {
namespace {

Point3 single(const Point3& p) { return Point3{float(p.x), float(p.y), float(p.z)}; }

// POV-Ray's max3_coordinate: the axis of the largest of x, y, z (ties to the later).
int largest_axis(Real x, Real y, Real z) {
    return x > y ? (x > z ? 0 : 2) : (y > z ? 1 : 2);
}

// A mesh's faces as the camera reads them (POV-Ray's Parse_Mesh and
// Compute_Mesh_Triangle): the face normal from the corners as written, the corners
// swapped as POV-Ray swaps them, unit vertex normals, and compute_smooth_triangle's Perp
// and vAxis; a smooth triangle whose normals are all alike is flat.
void add_faces(const Mesh& m, std::vector<MeshCamera::Face>& out) {
    constexpr Real kEpsilon = 1e-10;
    for (size_t i = 0; i < m->faces.size(); ++i) {
        const Mesh::Face& f = m->faces[i];
        MeshCamera::Face face;
        Point3 P[3];
        Vector3 N[3];
        Real U[3] = {0, 0, 0}, V[3] = {0, 0, 0};
        for (int k = 0; k < 3; ++k) {
            P[k] = m->vertices[f.v[k]];
            if (f.n[k] >= 0) {
                N[k] = m->normals[size_t(f.n[k])];
                if (std::fabs(N[k].x) < kEpsilon && std::fabs(N[k].y) < kEpsilon &&
                    std::fabs(N[k].z) < kEpsilon)
                    N[k] = Vector3{1, 0, 0};
                N[k] = N[k] / length(N[k]);
            }
            if (!m->uv_faces.empty()) {
                const auto& uv = m->uvs[m->uv_faces[i][size_t(k)]];
                U[k] = uv[0];
                V[k] = uv[1];
            }
        }
        if (f.n[0] >= 0) {
            const Vector3 d1 = N[0] - N[1], d2 = N[0] - N[2];
            face.smooth =
                std::fabs(dot(d1, d1)) > kEpsilon || std::fabs(dot(d2, d2)) > kEpsilon;
        }
        Vector3 normal = cross(P[2] - P[0], P[1] - P[0]);
        normal = normal / length(normal);
        face.normal = single(normal);
        bool swap = false;
        switch (
            largest_axis(std::fabs(normal.x), std::fabs(normal.y), std::fabs(normal.z))) {
            case 0:
                swap = (P[1].y - P[2].y) * (P[1].z - P[0].z) <
                       (P[1].z - P[2].z) * (P[1].y - P[0].y);
                break;
            case 1:
                swap = (P[1].x - P[2].x) * (P[1].z - P[0].z) <
                       (P[1].z - P[2].z) * (P[1].x - P[0].x);
                break;
            default:
                swap = (P[1].x - P[2].x) * (P[1].y - P[0].y) <
                       (P[1].y - P[2].y) * (P[1].x - P[0].x);
                break;
        }
        if (swap) {
            std::swap(P[0], P[1]);
            std::swap(U[0], U[1]);
            std::swap(V[0], V[1]);
            if (face.smooth) std::swap(N[0], N[1]);
        }
        // compute_smooth_triangle, on the corners as written (after the swap).
        const Vector3 p3p2 = P[2] - P[1];
        face.v_axis =
            largest_axis(std::fabs(p3p2.x), std::fabs(p3p2.y), std::fabs(p3p2.z));
        Vector3 t1 = normalize(P[1] - P[2]);
        const Vector3 t2 = P[0] - P[2];
        t1 = t1 * dot(t2, t1);
        Vector3 perp = normalize(t1 - t2);
        perp = perp / -dot(t2, perp);
        face.perp = single(perp);
        for (int k = 0; k < 3; ++k) {
            face.p[k] = single(P[k]);
            face.n[k] = face.smooth ? single(N[k]) : face.normal;
            face.u[k] = U[k];
            face.v[k] = V[k];
        }
        out.push_back(face);
    }
}

}  // namespace

std::shared_ptr<const MeshCamera> Interpreter::parse_mesh_camera(const Token& at) {
    expect_punct('{', "after 'mesh_camera'");
    auto mc = std::make_shared<MeshCamera>();
    const Token rays_at = peek();
    mc->rays_per_pixel = int(uint32_t(int64_t(parse_float())));
    if (mc->rays_per_pixel == 0) error(rays_at, "rays per pixel may not be 0");
    const Token method_at = peek();
    const double method = parse_float();
    if (method < 0 || method >= 4) error(method_at, "unrecognized distribution method");
    mc->distribution = int(method);
    if (mc->distribution >= 2 && mc->rays_per_pixel != 1)
        error(rays_at, "rays per pixel must be 1 for distribution method #2 or #3");
    if (starts_float(peek())) {
        const Token distance_at = peek();
        // POV-Ray ends the camera rays there (its maximum trace distance).
        if (parse_float() != 0) unsupported(distance_at, "mesh_camera maximum distance");
    }
    while (is_word(peek(), "mesh") || is_word(peek(), "mesh2")) {
        const Token t = next();
        Object o;
        try_parse_object(t, o);
        const Mesh* m = std::get_if<Mesh>(&o.shape);
        if (!m) expected("a mesh", t);
        MeshCamera::Part part;
        add_faces(*m, part.faces);
        part.transform = o.transform;
        mc->meshes.push_back(std::move(part));
    }
    if (accept_word("smooth")) {
        mc->smooth = true;
        if (mc->distribution != 3)
            error(at, "smooth can only be used with distribution method #3");
    }
    const Token close = next();
    if (!is_punct(close, '}')) expected("a mesh, mesh2, smooth or '}'", close);
    if (mc->meshes.empty()) expected("mesh or mesh2", close);
    if (mc->distribution == 0 && size_t(mc->rays_per_pixel) > mc->meshes.size())
        error(rays_at,
              "rays per pixel must be <= number of meshes for distribution method #0");
    uint32_t faces = 0;
    for (const MeshCamera::Part& p : mc->meshes)
        mc->face_ends.push_back(faces += uint32_t(p.faces.size()));
    if (mc->distribution == 3) {
        if (mc->meshes.size() > 1)
            warn(at,
                 "additional meshes after the first are ignored for distribution "
                 "method #3");
        const std::vector<MeshCamera::Face>& fs = mc->meshes[0].faces;
        const size_t words = (fs.size() + 31) / 32;
        for (int i = 0; i < 10; ++i) {
            mc->u_faces[size_t(i)].assign(words, 0);
            mc->v_faces[size_t(i)].assign(words, 0);
        }
        // Each face in the tenths of u and v its corners span (truncated as POV-Ray's
        // int conversion; a negative coordinate, which POV-Ray writes outside its
        // table, counts in the first tenth).
        for (size_t i = 0; i < fs.size(); ++i) {
            const MeshCamera::Face& f = fs[i];
            int u[3], v[3];
            for (int k = 0; k < 3; ++k) u[k] = int(f.u[k] * 10), v[k] = int(f.v[k] * 10);
            const int lo_u = std::max(0, std::min({u[0], u[1], u[2], 9}));
            const int lo_v = std::max(0, std::min({v[0], v[1], v[2], 9}));
            const int hi_u = std::min(std::max({u[0], u[1], u[2]}), 9);
            const int hi_v = std::min(std::max({v[0], v[1], v[2]}), 9);
            const uint32_t bit = uint32_t(1) << (i % 32);
            for (int k = lo_u; k <= hi_u; ++k) mc->u_faces[size_t(k)][i / 32] |= bit;
            for (int k = lo_v; k <= hi_v; ++k) mc->v_faces[size_t(k)][i / 32] |= bit;
        }
    }
    return mc;
}

}  // namespace povwall::parser
