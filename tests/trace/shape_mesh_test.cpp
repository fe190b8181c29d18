// mesh: the face tree's walks give exactly the crossings of a walk over every face in
// POV-Ray's order (each face's float box start, ties by index; a mesh without
// inside_vector stops at the first box that starts beyond its last kept hit), on
// triangle soups made to tie: coincident copies, faces in axis planes, rays along axes,
// restarted rays and clips. And the inside test counts every crossing.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "trace/pov_bounds.h"
#include "trace/shapes/mesh.h"
#include "trace/shapes/triangle.h"

namespace povwall::trace {
namespace {

struct Soup {
    std::shared_ptr<MeshData> data = std::make_shared<MeshData>();
    Mesh mesh() const {
        Mesh m;
        m.data = data;
        return m;
    }
};

// Faces of random size and place, a quarter in an axis plane, every tenth a copy of
// an earlier one (same corners: same box, same crossing), and one with a far corner.
Soup make_soup(std::mt19937_64& rng, int faces) {
    std::uniform_real_distribution<Real> place(-3, 3), size(0.05, 1.5);
    Soup s;
    MeshData& d = *s.data;
    for (int i = 0; i < faces; ++i) {
        MeshFace f;
        if (i > 10 && i % 10 == 0) {
            f = d.faces[size_t(rng() % d.faces.size())];
        } else {
            const Point3 c{place(rng), place(rng), place(rng)};
            const int flat = int(rng() % 4);  // 3: not flat
            for (int k = 0; k < 3; ++k) {
                Point3 p{c.x + size(rng) - 0.75, c.y + size(rng) - 0.75,
                         c.z + size(rng) - 0.75};
                if (flat < 3) p[flat] = std::round(c[flat]);
                f.v[k] = uint32_t(d.vertices.size());
                d.vertices.push_back(p);
            }
        }
        d.faces.push_back(f);
    }
    // One face reaching far out (an exporter's stray vertex): its box is huge, the
    // others' stay tight.
    MeshFace far;
    for (int k = 0; k < 3; ++k) far.v[k] = uint32_t(d.vertices.size() + size_t(k));
    d.vertices.push_back({0.5, 0.25, 0.5});
    d.vertices.push_back({0.75, 0.5, -0.25});
    d.vertices.push_back({0.5, 1e12, 0.5});
    d.faces.push_back(far);
    return s;
}

// The walk over every face, as POV-Ray's tree walk orders and ends it.
ShapeHits reference_hits(const Mesh& m, const LocalRay& r, const ShapeClip* clip) {
    const Vector3 unit = r.direction / r.length;
    ShapeHits out;
    struct Crossed {
        Real entry, t;
        int face;
    };
    std::vector<Crossed> crossed;
    const PovRay box_ray(r.origin, unit);
    for (size_t i = 0; i < m->faces.size(); ++i) {
        Point3 p[3];
        mesh_face_corners(m, m->faces[i], p);
        Crossings cs;
        intersect_triangle(p, r.origin, unit, cs);
        if (!cs.n) continue;
        if (!mesh_stops_at_nearest(m)) {
            if (!clip || clip->keeps(clip->context, cs.c[0].t / r.length))
                out.push_back({cs.c[0].t / r.length, {}, int(i)});
            continue;
        }
        if (!(cs.c[0].t / r.length > r.restart)) continue;
        Bounds3 box;
        for (const Point3& q : p) box.extend(q);
        Real entry = 0;
        if (!slab_tree_entry(pov_bbox(box), box_ray, entry)) continue;
        crossed.push_back({entry, cs.c[0].t, int(i)});
    }
    std::stable_sort(
        crossed.begin(), crossed.end(),
        [](const Crossed& a, const Crossed& b) { return a.entry < b.entry; });
    Real last_kept = kInfinity;
    for (const Crossed& c : crossed) {
        if (c.entry > last_kept) break;
        if (clip && !clip->keeps(clip->context, c.t / r.length)) continue;
        out.push_back({c.t / r.length, {}, c.face});
        last_kept = c.t;
    }
    return out;
}

LocalRay local_ray(const Point3& o, const Vector3& d, Real restart) {
    LocalRay r;
    r.origin = o;
    r.direction = d;
    r.length = length(d);
    r.unit = d / r.length;
    r.restart = restart;
    return r;
}

void expect_same(const ShapeHits& got, const ShapeHits& want) {
    ASSERT_EQ(got.size(), want.size());
    for (size_t i = 0; i < got.size(); ++i) {
        EXPECT_EQ(got[i].face, want[i].face) << i;
        EXPECT_EQ(got[i].t, want[i].t) << i;
    }
}

// Keeps crossings at world distances in [0, 2) and [4, 6).
bool banded(const void*, Real t) { return std::fmod(t, 4.0) < 2.0; }

TEST(ShapeMesh, TreeWalksEqualTheWalkOverEveryFace) {
    std::mt19937_64 rng(62);
    std::uniform_real_distribution<Real> place(-6, 6), dir(-1, 1);
    const ShapeClip clip{banded, nullptr};
    size_t stopped_early = 0, hits = 0;
    for (int mesh = 0; mesh < 6; ++mesh) {
        const Soup soup = make_soup(rng, 40 + 120 * mesh);
        for (bool tree : {true, false}) {
            Mesh m = soup.mesh();
            m.hierarchy = tree;
            for (int ray = 0; ray < 400; ++ray) {
                Point3 o{place(rng), place(rng), place(rng)};
                Vector3 d{dir(rng), dir(rng), dir(rng)};
                // Along an axis, or with one component zero; and scaled (a copy's ray).
                if (ray % 5 == 0) d = Vector3{0, 0, 0}, d[ray % 3] = ray % 2 ? 1 : -1;
                if (ray % 7 == 0) d[(ray / 7) % 3] = 0;
                if (!(length(d) > 0)) continue;
                d = d * (ray % 3 == 0 ? 2.5 : 1.0);
                const Real restart = ray % 4 == 0 ? 1.5 : 0.0;
                const LocalRay r = local_ray(o, d, restart);
                for (const ShapeClip* c :
                     {static_cast<const ShapeClip*>(nullptr), &clip}) {
                    ShapeHits got;
                    shape_hits(m, r, c, got);
                    const ShapeHits want = reference_hits(m, r, c);
                    SCOPED_TRACE(::testing::Message()
                                 << "mesh " << mesh << " ray " << ray);
                    expect_same(got, want);
                    hits += want.size();
                    if (c || !tree) continue;
                    // A closest-hit query gets the walk's nearest kept crossing (the
                    // first of equal ones), a shadow query whether there is one.
                    LocalRay nearest = r;
                    nearest.nearest_only = true;
                    const ShapeHit* first = nullptr;
                    for (const ShapeHit& h : want)
                        if (!first || h.t < first->t) first = &h;
                    ShapeHits one;
                    shape_hits(m, nearest, nullptr, one);
                    ASSERT_EQ(one.size(), first ? 1u : 0u);
                    if (first) {
                        EXPECT_EQ(one[0].t, first->t);
                        EXPECT_EQ(one[0].face, first->face);
                    }
                    nearest.any_crossing = true;
                    one.clear();
                    shape_hits(m, nearest, nullptr, one);
                    EXPECT_EQ(one.size(), first ? 1u : 0u);
                }
            }
        }
        // The walk stops before the farthest crossing on some rays (the case the order
        // decides).
        Mesh m = soup.mesh();
        for (int ray = 0; ray < 200; ++ray) {
            const LocalRay r = local_ray({place(rng), place(rng), -8}, {0, 0, 1}, 0);
            ShapeHits some, all;
            shape_hits(m, r, nullptr, some);
            m.hierarchy = false;
            shape_hits(m, r, nullptr, all);
            m.hierarchy = true;
            stopped_early += some.size() < all.size();
        }
    }
    EXPECT_GT(hits, 500u);
    EXPECT_GT(stopped_early, 10u);
}

TEST(ShapeMesh, InsideCountsEveryCrossingAlongTheInsideVector) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<Real> place(-4, 4);
    Soup soup = make_soup(rng, 300);
    soup.data->inside_vector = Vector3{0.3, 1, -0.2};
    const Mesh m = soup.mesh();
    const Vector3 dir = normalize(*soup.data->inside_vector);
    size_t inside = 0;
    for (int i = 0; i < 2000; ++i) {
        const Point3 q{place(rng), place(rng), place(rng)};
        int crossed = 0;
        for (const MeshFace& f : soup.data->faces) {
            Point3 p[3];
            mesh_face_corners(m, f, p);
            Crossings cs;
            intersect_triangle(p, q, dir, cs);
            crossed += cs.n;
        }
        EXPECT_EQ(shape_inside(m, q), crossed % 2 == 1) << i;
        inside += crossed % 2;
    }
    EXPECT_GT(inside, 100u);
}

TEST(ShapeMesh, CopiesShareOneFaceTree) {
    std::mt19937_64 rng(1);
    const Soup soup = make_soup(rng, 50);
    const Mesh a = soup.mesh(), b = soup.mesh();
    EXPECT_EQ(&a->tree(), &b->tree());
    // Every face in one leaf of at most four; a binary tree (2 leaves - 1 nodes).
    std::vector<int> seen(51, 0);
    size_t leaves = 0;
    for (const BoxTree::Node& n : a->tree().nodes()) {
        if (n.count == 0) continue;
        ++leaves;
        EXPECT_LE(n.count, 4u);
        for (uint32_t i = n.first; i < n.first + n.count; ++i)
            ++seen[a->tree().order()[i]];
    }
    EXPECT_EQ(a->tree().nodes().size(), 2 * leaves - 1);
    EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), 51);
}

}  // namespace
}  // namespace povwall::trace
