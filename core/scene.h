// The scene model: what the parser produces and every back end consumes.
//
// Plain data only. Shapes are structs in a variant; intersection lives in trace/.
// Every transform is stored object-to-world. The parser resolves POV-Ray's inheritance
// rules (textures pushed into CSG children, camera look_at/angle, #default), so consumers
// never need to know the scene language.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core/bicubic_patch.h"
#include "core/box_tree.h"
#include "core/colour.h"
#include "core/compact_transform.h"
#include "core/derived_slot.h"
#include "core/function.h"
#include "core/gamma.h"
#include "core/heap_optional.h"
#include "core/height_field.h"
#include "core/math.h"
#include "core/mesh.h"
#include "core/source_loc.h"

namespace povwall {

// ---------------------------------------------------------------- patterns and textures

enum class PatternKind : uint8_t {
    Solid,  // plain colour, no pattern
    Agate,
    Bozo,
    Brick,
    Bumps,
    Checker,
    Crackle,
    Dents,
    Gradient,
    Granite,
    Hexagon,
    Leopard,
    Mandel,
    Marble,
    Onion,
    Quilted,
    Radial,
    Ripples,
    Spiral1,
    Spiral2,
    Spotted,
    Waves,
    Wood,
    Wrinkles,
    Boxed,
    Cylindrical,
    Spherical,
    Planar,
    Average,
    ImageMap,
    Cells,
    Function,        // a user function of x, y, z (PatternSpec::function)
    PigmentPattern,  // the grey of a pigment (PatternSpec::pigment)
    Slope,           // the surface's slope (and altitude), PatternSpec::slope
    Aoi,             // the angle between the surface normal and the ray
    DensityFile,     // a df3 voxel grid over the unit cube, PatternSpec::density_file
    // `uv_mapping INNER` as a pigment's, normal's or texture's pattern: its one entry
    // (Pigment::maps->list[0], Normal::list[0], Texture::map->entries[0]) is evaluated
    // at the hit's surface coordinates (u, v, 0) (trace/uv_mapping.h).
    UvMapping,
    ObjectInside,  // `object { OBJ }`: 1 inside PatternSpec::object, else 0
    ImagePattern,  // `image_pattern { }`: an image's grey (PatternSpec::image)
    // `material_map { }`: the texture map entry an image's pixel indexes (a texture's
    // map pattern only, PatternSpec::image).
    MaterialMap,
    Square,      // four entries over the x-z unit squares
    Triangular,  // six entries over x-z triangles
    Cubic,       // six entries, one per face direction of a cube around the origin
    Julia,       // julia fractal in x-y (PatternSpec::fractal)
    Magnet,      // magnet 1 or 2, mandel or julia form (PatternSpec::fractal)
    Facets,      // normals only: flat facets (PatternSpec::facets)
    Tiling,      // `tiling N` in x-z (N in PatternSpec::scalar)
    Pavement,    // `pavement` in x-z (PatternSpec::pavement)
};

enum class WaveType : uint8_t { Ramp, Triangle, Sine, Scallop, Cubic, Poly };

struct Warp {
    enum class Kind : uint8_t {
        Turbulence,
        Repeat,
        BlackHole,
        Cylindrical,
        Spherical,
        Toroidal,
        Planar,
        Cubic  // the six faces of a cube around the origin onto a cross in x-y
    } kind = Kind::Turbulence;
    Vector3 turbulence{0, 0, 0};
    int octaves = 6;
    Real omega = 0.5, lambda = 2.0;
    Vector3 repeat{0, 0, 0}, offset{0, 0, 0}, flip{0, 0, 0};  // repeat warp
    // Turbulence only: true for the pattern's classic `turbulence` keyword (POV-Ray
    // applies it last and marble/wood/spiral/agate read it), false for `warp { turbulence
    // }`.
    bool classic = true;
    // black_hole: centre, radius, strength, falloff, inverse; its `repeat` vector and its
    // `turbulence` (the position uncertainty) use the fields above.
    Point3 centre{0, 0, 0};
    Real radius = 1, strength = 1, falloff = 2;
    bool inverse = false;
    // cylindrical/spherical/toroidal/planar warps: orientation, dist_exp, toroidal
    // major_radius, planar offset.
    Vector3 orientation{0, 0, 1};
    Real dist_exp = 0, major_radius = 1, plane_offset = 0;
    // The transforms written before this warp (after the previous one): on the way
    // from world to pattern space their inverse applies after the warp.
    Transform transform;
};

// The pixels of an image_map / bump_map file after POV-Ray's gamma decoding:
// working-space colour plus filter and transmit (transmit from the file's alpha), top row
// first.
struct ImagePixels {
    int width = 0, height = 0;
    // The pixels, in one of two forms. An 8-bit file's (not a palette's): 4 codes a pixel
    // (red, green, blue, alpha as stored), each colour code's value in `decoded` (its
    // gamma decoding done once), transmit 1 - alpha / 255 when the file has alpha; 4
    // bytes a pixel where floats took 20 (a 4096x2048 texture: 168 MB). Otherwise
    // `rgbft`, 5 floats a pixel (palette images have filter and transmit per entry).
    std::vector<uint8_t> codes;
    std::array<float, 256> decoded{};
    bool codes_alpha = false;  // the codes' alpha is the file's (else transmit 0)
    std::vector<float> rgbft;
    // A palette file's index of each pixel (bump_map use_index reads it); else empty.
    std::vector<uint8_t> indices;
    int palette_size = 0;
    // Whether some pixel has filter or transmit (set once the pixels are final: every
    // object's material asks, and a scan per object cost minutes on large scenes).
    bool see_through = false;
    void note_see_through() {
        see_through = false;
        if (!codes.empty()) {
            for (size_t i = 3; codes_alpha && i < codes.size() && !see_through; i += 4)
                see_through = codes[i] != 255;
            return;
        }
        for (size_t i = 0; i + 4 < rgbft.size() && !see_through; i += 5)
            see_through = rgbft[i + 3] != 0 || rgbft[i + 4] != 0;
    }
    // The pixel's red, green, blue, filter and transmit.
    void fetch(int x, int y, float out[5]) const {
        const size_t at = size_t(y) * size_t(width) + size_t(x);
        if (!codes.empty()) {
            const uint8_t* c = &codes[at * 4];
            out[0] = decoded[c[0]];
            out[1] = decoded[c[1]];
            out[2] = decoded[c[2]];
            out[3] = 0;
            // As the float form: 1 - the sample (code * (1 / 255)).
            out[4] = codes_alpha ? 1.0f - float(c[3]) * (1.0f / 255.0f) : 0.0f;
            return;
        }
        const float* f = &rgbft[at * 5];
        for (int i = 0; i < 5; ++i) out[i] = f[i];
    }
};

// image_map { } / bump_map { }: the file and how it is laid onto pattern space.
struct ImageMapping {
    std::string path;  // as resolved by the include search rules
    // Null when the scene was parsed without an image reader
    // (ParseOptions::image_reader).
    std::shared_ptr<const ImagePixels> pixels;
    int map_type = 0;     // 0 planar, 1 spherical, 2 cylindrical, 5 torus; else planar
    int interpolate = 0;  // 0 none, 2 bilinear, 3 bicubic, 4 normalised distance
    bool once = false;
    // image_pattern's value: 0 the grey, 1 the transmit (use_alpha, an image with an
    // alpha channel), 2 the red (use_alpha, an image without).
    uint8_t image_value = 0;
    // bump_map: heights are palette indices (ImagePixels::indices); for other images
    // the colours' grey, as use_color.
    bool use_index = false;
    float all_filter = 0, all_transmit = 0;
    // The pixels' colours are premultiplied by their opacity (POV-Ray's default for TIFF
    // and OpenEXR, `premultiplied` for any file): an image_map pigment divides its sample
    // by 1 - transmit (`transmit all` included), as POV-Ray's image_map does.
    bool premultiplied = false;
    Real width = 0, height = 0;  // image size in pixels times the `repeat` vector
    Real offset_u = 0,
         offset_v = 0;  // `offset` in pixels (negated, as POV-Ray stores it)
};

// A df3 file (`density_file df3 "name"`): its sizes and its voxels, x fastest, then y,
// then z, as read from the file's big-endian 8, 16 or 32 bit values.
struct DensityFile {
    std::string path;  // as resolved by the include search rules
    uint32_t size_x = 0, size_y = 0, size_z = 0;
    int bytes_per_voxel = 1;  // 1, 2 or 4: the value that reads as 1 is 2^(8 bytes) - 1
    std::vector<uint32_t> voxels;
};

struct Pigment;
struct Object;

// Everything that turns a point into a pattern value in [0,1].
struct PatternSpec {
    PatternKind kind = PatternKind::Solid;
    Vector3 vector{0, 0, 0};   // gradient direction; brick size; mortar in scalar below
    Real scalar = 0;           // agate_turb, mortar, spiral arms, mandel iterations, ...
    Vector3 vector2{0, 0, 0};  // secondary parameter (brick: mortar as vector unused)
    Real frequency = 1, phase = 0;
    WaveType wave = WaveType::Ramp;
    Real wave_exponent = 1;
    int noise_generator = 0;  // 0: inherit global setting
    // `no_bump_scale` (POV-Ray's DONT_SCALE_BUMPS_FLAG, which it keeps on the pattern):
    // a normal taken into this pattern's space and back is not renormalised, so the
    // pattern's and object's scaling changes the bumps' slopes. Set on a normal's
    // pattern, and on a texture_map's (whose entries' normals the parser hands it to).
    bool no_bump_scale = false;
    // Classic turbulence keyword applied before the pattern (ordered after warps as
    // POV-Ray does).
    std::vector<Warp> warps;
    // The transforms written after the last warp (all of them when there is none),
    // object transforms included: its inverse applies to hit points first.
    CompactTransform transform;
    // Mandel, julia and magnet (iterations in `scalar`): how points that escape
    // (exterior, types 0-8) and points that stay (interior, types 0-6) get their value,
    // each with its factor (POV-Ray's defaults); the exponent (2-33, mandel and julia),
    // julia's constant, and magnet's formula (1 or 2) and form (mandel or julia).
    struct Fractal {
        uint8_t exterior_type = 1, interior_type = 0;
        Real exterior_factor = 1, interior_factor = 1;
        uint8_t exponent = 2;
        uint8_t magnet_formula = 1;
        bool magnet_julia = false;
        Real c_re = 0, c_im = 0;  // julia (and magnet julia) constant
    } fractal;
    // Facets only: `coords` (0: facets follow the normal, else the point and the
    // perturbation's weight), `size` and `metric`.
    struct Facets {
        Real coords = 0, size = 0.1, metric = 2;
    } facets;
    // Pavement only: the tiles' sides (3, 4 or 6), how many cells a tile has, which of
    // the tilings of such tiles (1 up to pavement_patterns), and the look of the
    // outline's corners (0 sharp, 1 chamfered, 2 round; form 3, squares only: none).
    // POV-Ray keeps each as an unsigned char and the parser reduces exterior and
    // interior modulo 3 and form modulo 4 (squares) or 3.
    struct Pavement {
        uint8_t sides = 3, tiles = 1, pattern = 1;
        uint8_t exterior = 0, interior = 0, form = 0;
    } pavement;
    // Slope only (PatternSpec::slope), as POV-Ray keeps it: the unit directions (or
    // point_at's point), each modulation as (low, high - low), 0 range for none, and the
    // shares of slope and altitude in the value. `axis` is +-(1 + index) when a
    // direction is an exact unit axis (POV-Ray reads that component directly), else 0.
    struct Slope {
        Vector3 direction{0, 0, 0}, altitude{0, 0, 0};
        Real low = 0, range = 0, altitude_low = 0, altitude_range = 0;
        Real share = 1, altitude_share = 0;
        int8_t axis = 0, altitude_axis = 0;
        bool point_at = false;
    };
    std::shared_ptr<const Slope> slope;               // PatternKind::Slope only
    std::shared_ptr<const ImageMapping> image;        // PatternKind::ImageMap only
    std::shared_ptr<const FunctionProgram> function;  // PatternKind::Function only
    std::shared_ptr<const Pigment> pigment;           // PatternKind::PigmentPattern only
    std::shared_ptr<const Object> object;             // PatternKind::ObjectInside only
    // PatternKind::DensityFile only: the file (shared by every copy of the pattern) and
    // `interpolate` as written (POV-Ray reads it modulo 10: 0 none, 1 trilinear, else
    // tricubic).
    std::shared_ptr<const DensityFile> density_file;
    int density_interpolation = 0;
};

struct ColourMapEntry {
    float value;
    Colour colour;
};
using ColourMap = std::vector<ColourMapEntry>;

struct Pigment;
// What a patterned pigment maps its pattern's values to; solid pigments leave it unset.
struct PigmentMaps {
    ColourMap colour_map;
    std::vector<float> map_values;  // pigment_map values, parallel to `list`
    std::vector<Pigment> list;  // checker/hexagon/brick entries, or pigment_map entries
    std::optional<Colour> quick_colour;
};

// A solid pigment is its colour and two unset pointers (40 bytes): scenes of many
// solid-coloured objects page in little more than the colours.
struct Pigment {
    HeapValue<PatternSpec> pattern;  // solid pigments never write it
    Colour colour;  // Solid pigments; also the colour a scene gets by default
    HeapValue<PigmentMaps> maps;
};

// slope_map entry: at pattern value `value`, the surface height and its slope.
struct SlopeMapEntry {
    float value;
    Real height, slope;
};

struct Normal {
    HeapValue<PatternSpec> pattern;
    Real amount = 0.5;  // bump_size
    std::vector<float> map_values;
    std::vector<Normal> list;  // normal_map entries
    std::vector<SlopeMapEntry> slope_map;
    Real accuracy = 0.02;
};

struct Finish {
    Rgb ambient{0.1f};
    Rgb emission{0.0f};
    float diffuse = 0.6f, brilliance = 1.0f, crand = 0.0f;
    float diffuse_back = 0.0f;  // `diffuse a, b`: light arriving from behind the surface
    // diffuse and diffuse back before `albedo` scaled them (POV-Ray's RawDiffuse: what
    // radiosity's ambient light is multiplied by).
    float raw_diffuse = 0.6f, raw_diffuse_back = 0.0f;
    float phong = 0.0f, phong_size = 40.0f;
    float specular = 0.0f, roughness = 0.05f;
    float metallic = 0.0f;
    Rgb reflection_min{0.0f}, reflection_max{0.0f};
    float reflection_falloff = 1.0f, reflection_exponent = 1.0f,
          reflection_metallic = 0.0f;
    bool reflection_fresnel = false;
    bool conserve_energy = false;
    float irid = 0.0f, irid_thickness = 0.0f, irid_turbulence = 0.0f;
    // POV-Ray's old `finish { ior, caustics, refraction }`: moved into the object's
    // interior when the object is placed (ior and caustics negative: not given).
    float legacy_ior = -1.0f, legacy_caustics = -1.0f, legacy_refraction = 1.0f;
    // finish { subsurface { translucency, anisotropy } }: POV-Ray 3.7's experimental
    // subsurface light transport (trace/subsurface.h). translucency: the reduced
    // scattering mean free path, mm per channel; anisotropy is kept unused, as in 3.7.
    bool subsurface = false;
    Rgb translucency{0.0f}, anisotropy{0.0f};
    bool operator==(const Finish&) const = default;
};

struct Texture;
// The entries a patterned texture selects among (texture_map, material_map, checker of
// textures); each entry may itself be layered.
struct TextureMap {
    std::vector<float> values;  // map values, parallel to `entries` (empty: by index)
    std::vector<std::vector<Texture>> entries;
};

// A texture with a solid pigment and no normal or map is 80 bytes: its colour and four
// pointers, three of them unset.
struct Texture {
    Pigment pigment;
    HeapOptional<Normal> normal;
    SharedValue<Finish> finish;  // objects with equal finishes share one
    // Patterned texture: when `map` has entries the fields above are unused and the
    // pattern selects among them.
    HeapOptional<PatternSpec> map_pattern;
    HeapValue<TextureMap> map;
};
using LayeredTexture = std::vector<Texture>;  // layers, bottom first

// A participating medium (POV-Ray 3.7's `media { }`), in an interior or the scene's
// atmosphere. Defaults are the 3.5+ ones; the parser sets the older ones (method 1,
// intervals 10, samples 1) for media parsed under #version < 3.5.
struct Media {
    int method = 3;
    int intervals = 1;
    int samples_min = 10, samples_max = 10;
    int aa_level = 3;
    float aa_threshold = 0.1f;
    float jitter = 0.0f;
    float ratio = 0.9f;
    float confidence = 0.9f, variance = 1.0f / 128;
    Rgb absorption{0.0f}, emission{0.0f};
    // The densities multiply channel by channel; none: 1 everywhere. World space (an
    // object's transforms move its interior's densities).
    std::vector<Pigment> density;
    bool collect = true;
    // `scattering { type, colour [eccentricity e] [extinction x] }`: light from the
    // scene's lights scattered toward the viewer. Types 1 isotropic, 2 Mie haze, 3 Mie
    // murky, 4 Rayleigh, 5 Henyey-Greenstein (eccentricity); others act as type 1.
    int scattering_type = 1;
    Rgb scattering{0.0f};
    float eccentricity = 0;
    float scattering_extinction = 1;  // how much the scattering also dims (POV's sc_ext)
    SourceLoc scattering_loc;         // where it was given (refusals name it)
    bool scatters() const { return !scattering.is_black(); }
    Rgb extinction() const { return absorption + scattering * scattering_extinction; }
};

struct Interior {
    float ior = 1.0f;
    // `ior` was given: without it POV-Ray takes the atmosphere's index and dispersion
    // (both 1), so a lone `dispersion` does nothing.
    bool ior_set = false;
    float caustics = 0.0f;  // faked caustics, as POV-Ray stores it (interior{}: x45)
    float dispersion = 1.0f;
    int dispersion_samples = 7;
    float fade_distance = 0.0f, fade_power = 0.0f;
    Rgb fade_colour{0.0f};
    float old_refract = 1.0f;  // `refraction`: scales what passes each surface
    // Fog and media fill it (POV-Ray keeps `hollow` in the interior, which its sharers
    // set in turn as they are placed).
    bool hollow = false;
    std::vector<Media> media;  // in parse order
    // Which interior this is. As POV-Ray shares one interior between a CSG and the
    // children without their own, so that a ray leaving one of them leaves all, objects
    // that share one carry the same id; object{} copies get their own. The parser numbers
    // them when it places an object in the scene (0: not numbered).
    uint32_t id = 0;
};
// Whether an interior acts as none at all (ior 1, no media, fade, caustics or refraction
// scale, default dispersion), its id and hollow flag aside. A field added to Interior is
// added here.
bool interior_is_default(const Interior& in);

// ---------------------------------------------------------------- shapes (object space)

// POV-Ray moves a sphere's centre and scales its radius for translate, rotate and a
// uniform scale; the first other transform (a scale unequal in any component, a sign
// included, or a matrix) makes it keep a matrix, into which every later transform goes.
// Its box is then that matrix applied to the cube around the centre and radius it had
// (Sphere::Compute_BBox): a turned cube's box, larger than the sphere's. The surface is
// the same either way; povwall keeps the whole transform on the object and this only
// for the box.
struct SpherePovMatrix {
    Point3 centre;  // in world space before `rest`
    Real radius = 1;
    Transform rest;
};
struct Sphere {
    Point3 centre;
    Real radius = 1;
    std::shared_ptr<const SpherePovMatrix> pov_matrix = nullptr;  // none kept by POV-Ray
};
struct Box {
    Point3 corner1, corner2;
};
struct Plane {
    Vector3 normal{0, 1, 0};
    Real distance = 0;
};  // dot(n, p) = distance
struct Cylinder {
    Point3 base, cap;
    Real radius = 1;
    bool open = false;
};
struct Cone {
    Point3 base, cap;
    Real base_radius = 1, cap_radius = 0;
    bool open = false;
};
struct Torus {
    Real major = 1, minor = 0.25;
    bool sturm = false;
};
struct Disc {
    Point3 centre;
    Vector3 normal{0, 1, 0};
    Real radius = 1, hole_radius = 0;
};
struct Triangle {
    Point3 p[3];
};
struct SmoothTriangle {
    Point3 p[3];
    // Vertex normals on the heap: inline they made every object's shape 152 bytes.
    HeapValue<std::array<Vector3, 3>> n;
};
struct Polygon {
    std::vector<Point3> points;
};  // parser stores the plane-projected loop

// A mesh object: the shared geometry (core/mesh.h) and what belongs to this copy.
struct Mesh {
    using Face = MeshFace;
    std::shared_ptr<const MeshData> data;
    std::vector<LayeredTexture> textures;  // per-face textures (mesh2 texture_list)
    // How many of the scene's objects hold this mesh's data (the parser counts them,
    // left-out objects too, so every process of a render agrees). A mesh whose copies
    // would make more than kInstancedTriangles triangles is traced whole through its face
    // tree, each copy with its own transform; fewer are split into triangles of their own
    // (their rays are cheaper that way, and their set-up small).
    uint32_t copies = 1;
    static constexpr uint64_t kInstancedTriangles = 65536;
    // `hierarchy` inside the mesh's own braces (POV-Ray builds the mesh's box tree after
    // them): without the tree, every crossing is reported, even without inside_vector.
    bool hierarchy = true;
    const MeshData* operator->() const { return data.get(); }
    bool instanced() const {
        return copies > 1 && uint64_t(copies) * data->faces.size() > kInstancedTriangles;
    }
};

// prism: closed 2-D curves in (x, z) swept along y from height1 to height2, straight
// (linear_sweep) or scaled towards the origin (conic_sweep, the curve at y = 1). The
// parser turns the points into cubic segments as POV-Ray's Compute_Prism does:
// (u, v)(t) = a t^3 + b t^2 + c t + d for t in [0, 1]; trace/shapes/prism.cpp.
struct PrismSegment {
    Real a[2], b[2], c[2], d[2];  // [0]: u (x), [1]: v (z)
    // The segment's rectangle in (x, z), scaled over the heights for conic_sweep, and
    // the unscaled extent of the curve (x2, y1, y2 before scaling).
    Real x1, x2, y1, y2;
    Real u2, v1, v2;
};
struct Prism {
    enum class Spline : uint8_t { Linear, Quadratic, Cubic, Bezier };
    Spline spline = Spline::Linear;
    bool conic = false;
    bool open = false;
    bool sturm = false;
    bool degenerate = false;  // a curve left open: never hit (POV-Ray's DEGENERATE_FLAG)
    Real height1 = 0, height2 = 1;
    Real x1 = 0, x2 = 0, y1 = 0, y2 = 0;  // all segments' rectangle (conic: scaled)
    Real u1 = 0, u2 = 0, v1 = 0, v2 = 0;  // the curves' own extent
    std::vector<PrismSegment> segments;
};

// bicubic_patch: control points and pieces on the heap, shared by copies (a transform
// makes new ones: core/bicubic_patch.h).
struct BicubicPatch {
    std::shared_ptr<const BicubicPatchData> data;
};

// julia_fractal: the 3-D slice of a 4-D Julia set of q -> f(q) + c, quaternion or
// hypercomplex, as POV-Ray 3.7's (trace/shapes/julia_fractal.cpp).
struct JuliaFractal {
    enum class Algebra : uint8_t { Quaternion, Hypercomplex };
    // Hypercomplex only past Reciprocal: a complex function applied to both parts of the
    // duplex form (POV-Ray's hcmplx functions); Pwr raises to the complex `exponent`.
    enum class Function : uint8_t {
        Sqr,
        Cube,
        Reciprocal,
        Exp,
        Ln,
        Sin,
        Asin,
        Cos,
        Acos,
        Tan,
        Atan,
        Sinh,
        Asinh,
        Cosh,
        Acosh,
        Tanh,
        Atanh,
        Pwr
    };
    std::array<Real, 4> c{0, 0, 0, 0};
    std::array<Real, 2> exponent{0, 0};  // pwr's (re, im)
    Algebra algebra = Algebra::Quaternion;
    Function function = Function::Sqr;
    int max_iteration = 20;
    std::array<Real, 4> slice{0, 0, 0, 1};  // unit
    Real slice_distance = 0;
    Real precision = 1.0 / 20;          // the marching step: 1 / `precision`
    Real radius2 = 4, exit_value = 16;  // bounding sphere and escape value (set up)
};

// One character of a `text` object: a TrueType outline in em units (x right, y up,
// baseline y = 0) extruded from z = 0 to z = depth. The parser builds the outline as
// POV-Ray reads it (parser/truetype_font.h); glyphs of one font share it.
struct GlyphSegment {
    Real x[3], y[3];  // start, control, end (a line: start x[0] and end x[1])
    bool curve;
};
struct GlyphOutline {
    std::vector<GlyphSegment> segments;  // every contour's, in file order
    // POV-Ray's box of the glyph in em units: the header's, widened by the points.
    Real xmin = 0, ymin = 0, xmax = 0, ymax = 0;
    // The box of the segments' points (in the segments' units): no segment leaves it, so
    // rays and points outside it skip the per-segment work. Unbounded until index()
    // (an outline built without it skips nothing).
    Real point_xmin = -kInfinity, point_xmax = kInfinity;
    Real point_ymin = -kInfinity, point_ymax = kInfinity;

    // Segments by horizontal band of the point box: band k's set (bits in file order)
    // holds every segment whose points' y range meets the band, so a test at height y,
    // or over a range of heights, visits only the segments that can cross it (a curve
    // lies in its points' hull). Empty until index().
    static constexpr int kBands = 32;
    int band_words = 0;               // 64-bit words per band's set
    std::vector<uint64_t> band_sets;  // kBands * band_words
    Real band_scale = 0;              // bands per unit of y

    // The band of height y (monotone in y, so a segment from y0 to y1 is in every band
    // from band(y0) to band(y1)).
    int band(Real y) const {
        const Real f = (y - point_ymin) * band_scale;
        if (!(f > 0)) return 0;
        return f >= kBands ? kBands - 1 : int(f);
    }
    const uint64_t* band_set(int k) const { return band_sets.data() + k * band_words; }
    // Sets the point box and the bands from the segments.
    void index();
};
struct Glyph {
    std::shared_ptr<const GlyphOutline> outline;
    Real depth = 1;
};
// superellipsoid { <e, n> }: (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) = 1 in the unit
// cube. POV-Ray keeps only the exponents 2/e and 2/n.
struct Superellipsoid {
    Real east_west = 1, north_south = 1;  // e and n as written
};

// ovus { B, T }: a sphere of radius B at the origin and one of radius T at (0, B, 0),
// joined by a band of a spindle torus about y whose profile circle (radius Rc, centre
// Hp across the axis, at height Vp) touches both spheres. Built by make_ovus.
struct Ovus {
    Real bottom_radius = 1, top_radius = 0.5;
    Real band_radius = 0, band_offset = 0, band_height = 0;  // Rc, Hp, Vp
    Real band_bottom = 0, band_top = 0;  // the band lies strictly between these heights
    bool sturm = false;
};
// The band of an ovus, computed as POV-Ray's parser does (0 <= top < 2 bottom).
Ovus make_ovus(Real bottom_radius, Real top_radius);

// A profile point of a lathe or sor: x is the radius, y the height.
struct ProfilePoint {
    Real x = 0, y = 0;
};

// POV-Ray's bounding cylinders of a lathe's or sor's segments (its BCyl): the distinct
// squared radii and heights, and per segment the indices of its inner and outer radius
// and of its bottom and top height. Built by make_bounding_cylinders.
struct BoundingCylinders {
    std::vector<Real> radii2, heights;
    struct Segment {
        uint32_t r1, r2, h1, h2;
    };
    std::vector<Segment> segments;
};
BoundingCylinders make_bounding_cylinders(const std::vector<Real>& r1,
                                          const std::vector<Real>& r2,
                                          const std::vector<Real>& h1,
                                          const std::vector<Real>& h2);

// sor { N, <r, h>... }: per segment, r^2 as a cubic in height.
struct SorSpline {
    struct Segment {
        Real a, b, c, d;  // r^2 = a h^3 + b h^2 + c h + d
    };
    std::vector<Segment> segments;
    BoundingCylinders cylinders;
    Real radius1 = 0, radius2 = 0, height1 = 0, height2 = 0;  // overall bounds
    Real base_radius2 = 0, cap_radius2 = 0;                   // the end caps
};
struct Sor {
    std::shared_ptr<const SorSpline> spline;  // shared by copies, as in POV-Ray
    bool open = false, sturm = false;
};
// The spline through `points` as POV-Ray's Compute_Sor builds it, or POV-Ray's error
// message (a segment without height, a singular interpolation matrix).
std::string make_sor_spline(const std::vector<ProfilePoint>& points, SorSpline& out);

// lathe { SPLINE N, <r, h>... }: per segment, the radius and the height as cubics in a
// parameter t in [0, 1].
enum class LatheSplineKind : uint8_t { Linear, Quadratic, Cubic, Bezier };
struct LatheSpline {
    struct Segment {
        Real ar, br, cr, dr;  // r(t) = ((ar t + br) t + cr) t + dr
        Real aw, bw, cw, dw;  // the height w(t) likewise
    };
    LatheSplineKind kind = LatheSplineKind::Linear;
    std::vector<Segment> segments;
    BoundingCylinders cylinders;
    Real radius1 = 0, radius2 = 0, height1 = 0, height2 = 0;  // overall bounds (signed r)
};
struct Lathe {
    std::shared_ptr<const LatheSpline> spline;  // shared by copies, as in POV-Ray
    bool sturm = false;
};
// The spline through `points` as POV-Ray's Compute_Lathe builds it (the point count
// suits the kind: the parser checks it).
LatheSpline make_lathe_spline(LatheSplineKind kind,
                              const std::vector<ProfilePoint>& points);

// height_field: its grid shared by copies, as POV-Ray's (core/height_field.h). The
// object's transform starts with the scale that maps the grid to the unit square.
struct HeightField {
    std::shared_ptr<const HeightFieldData> data;
    bool smooth = false;
    // The `hierarchy` modifier as last given; the grid's blocks were built with the value
    // it had when the height_field block closed (later ones, on a copy, change nothing).
    bool hierarchy = true;
};
// sphere_sweep { SPLINE N, <centre>, radius ... [tolerance T] }: a sphere moved along a
// spline, its radius interpolated too. Per segment the centre and the radius are
// polynomials in u in [0, 1] (linear: degree 1; Catmull-Rom and B-spline: degree 3).
enum class SweepSpline : uint8_t { Linear, CatmullRom, BSpline };
struct SweepSphere {
    Point3 centre;
    Real radius;  // negative after a negative uniform scale, as in POV-Ray
};
struct SweepSegment {
    int coefficients = 2;  // 2 (linear) or 4 (cubic)
    // centre(u) = sum centre_coef[k] u^k, radius(u) likewise.
    Vector3 centre_coef[4] = {};
    Real radius_coef[4] = {};
    // The spheres at u = 0 and u = 1 and the derivatives there (the end caps' planes).
    SweepSphere closing[2] = {};
    Vector3 centre_deriv[2] = {};
    Real radius_deriv[2] = {};
};
struct SphereSweepData {
    SweepSpline spline = SweepSpline::Linear;
    std::vector<SweepSphere> modeling;  // as given, then moved by baked transforms
    std::vector<SweepSegment> segments;
    std::vector<SweepSphere>
        joints;  // each segment's first sphere, and the last one's end
};
struct SphereSweep {
    std::shared_ptr<const SphereSweepData> data;  // shared by copies
    Real tolerance = 1e-6;                        // the depth tolerance (world distance)
    // POV-Ray moves the spheres themselves for translate, rotate and uniform scale until
    // another transform makes it keep a matrix (Object::transform); from then on every
    // transform goes into the matrix, and rays are met in its space.
    bool has_matrix = false;
};
// The segments and joint spheres as POV-Ray's SphereSweep::Compute builds them from the
// modeling spheres (their count suits the spline: the parser checks it).
SphereSweepData make_sphere_sweep(SweepSpline spline, std::vector<SweepSphere> modeling);

// poly { N, <coefficients> } (cubic: N = 3, quartic: N = 4, polynomial: by terms):
// F(x, y, z) = sum of coeffs[k] x^i y^j z^l = 0, the terms in POV-Ray's order (i from N
// down, then j, then l; trace/shapes/poly.h). Inside is F < 1e-4.
struct Poly {
    int order = 2;
    std::vector<Real> coeffs;  // (N+1)(N+2)(N+3)/6 of them
    bool sturm = false;
};

// quadric { <A,B,C>, <D,E,F>, <G,H,I>, J }: A x^2 + B y^2 + C z^2 + D xy + E xz + F yz
// + G x + H y + I z + J = 0 in WORLD space: as POV-Ray, every transform is folded into
// the coefficients (the object's transform stays the identity), and the quadric keeps
// POV-Ray's own single-precision box, computed and moved as POV-Ray does
// (trace/shapes/quadric.h).
struct Quadric {
    Vector3 square{1, 1, 1}, mixed{0, 0, 0}, linear{0, 0, 0};
    Real constant = -1;
    float box_lo[3] = {-1e10f, -1e10f, -1e10f};
    float box_len[3] = {2e10f, 2e10f, 2e10f};
    bool automatic_bounds = false;
};

// blob { [threshold T] sphere { <C>, R, [strength] S } cylinder { <B>, <A>, R, S }
// component S, R, <C> ... }: the field sum of S (1 - r^2/R^2)^2 over the elements with
// r < R, the surface where it equals the threshold (trace/shapes/blob.h). Elements are
// stored as POV-Ray's Make_Blob leaves them: in reverse source order, a cylinder as its
// body followed by its base and apex hemispheres (all three sharing its matrix).
enum class BlobElementKind : uint8_t {
    Sphere,          // centre `origin` in blob space, no matrix
    Ellipsoid,       // a sphere given a matrix: centre `origin` in its own space
    Cylinder,        // its own space: axis z from 0 to `len`, x^2 + y^2 the distance
    BaseHemisphere,  // |p|^2 for z <= 0
    ApexHemisphere,  // |p - len z|^2 for z >= len
};
struct BlobElement {
    BlobElementKind kind = BlobElementKind::Sphere;
    Point3 origin{0, 0, 0};
    Real len = 0;   // a cylinder's (and its hemispheres') length
    Real rad2 = 0;  // radius squared
    // The field as c[0] r^4 + c[1] r^2 + c[2] (c[2] is the strength).
    Real c[3] = {0, 0, 0};
    Transform transform;  // element space -> blob space (ellipsoid, cylinder parts)
};
struct BlobData {
    Real threshold = 1;
    std::vector<BlobElement> elements;
    // Over blob_element_box of each element (make_blob builds it; empty: every element
    // is visited).
    BoxTree tree;
};
struct Blob {
    std::shared_ptr<const BlobData> data;  // shared by copies
    bool sturm = false;
    bool hierarchy = true;  // POV-Ray's bounding-sphere tree: visiting order only
    // Per element (in the stored order) the texture its component was given, empty for
    // none (the blob's own texture stands in); no entries when no component has one.
    // A hit blends them weighted by each element's |field| there.
    std::vector<LayeredTexture> element_textures;
};
// The element list as POV-Ray's Make_Blob builds it from the components as parsed (in
// source order; cylinders with their matrix and length, spheres perhaps ellipsoids, c[2]
// the strength): reversed, cylinders expanded, the field coefficients filled in.
BlobData make_blob(Real threshold, const std::vector<BlobElement>& components);
// A box in blob space holding the element's region (where its field is not zero), a
// little larger than it so that rounding in the element's own tests stays inside.
Bounds3 blob_element_box(const BlobElement& e);

// isosurface { function { F } contained_by { box | sphere } threshold accuracy
// max_gradient max_trace open }: F(x, y, z) - threshold = 0 inside its container, found
// along the ray by POV-Ray 3.7's recursive subdivision (trace/shapes/isosurface.h).
// What the root searches of one parsed isosurface and of its copies met (POV-Ray's
// shared mginfo), for its end-of-render max_gradient and evaluate messages
// (IsoSurface::DispatchShutdownMessages). Every tracing thread writes it.
struct IsosurfaceGradients {
    SourceLoc function_at;  // where POV-Ray's message points: the function
    // The steepest |f(b) - f(a)| / |b - a| between two samples of a search.
    std::atomic<double> found{0};
    // With `evaluate`, over the searches that found a root: the largest estimate, the
    // largest change of it in one search, their sum and count.
    std::atomic<double> eval_max{0}, eval_var{0}, eval_sum{0};
    std::atomic<uint64_t> eval_count{0};

    static void raise(std::atomic<double>& to, double v) {
        double now = to.load(std::memory_order_relaxed);
        while (v > now && !to.compare_exchange_weak(now, v, std::memory_order_relaxed)) {
        }
    }
    static void add(std::atomic<double>& to, double v) {
        double now = to.load(std::memory_order_relaxed);
        while (!to.compare_exchange_weak(now, now + v, std::memory_order_relaxed)) {
        }
    }
};

struct Isosurface {
    std::shared_ptr<const FunctionProgram> function;  // a float function of x, y, z
    bool sphere_container = false;
    Point3 corner1{-1, -1, -1}, corner2{1, 1, 1};  // the box (sorted per axis)
    Point3 centre{0, 0, 0};
    Real radius = 1;
    Real threshold = 0, accuracy = 0.001, max_gradient = 1.1;
    int max_trace = 1;
    bool closed = true;
    // `evaluate P0, P1, P2`: max_gradient adapts along each ray (POV-Ray's dynamic
    // estimate: above P0 it decays by P2, below P1 times a gradient seen it grows to P1^2
    // times that).
    bool evaluate = false;
    Real eval_param[3] = {0, 0, 0};
    // The global settings the function's patterns and f_noise3d read (set when the
    // parse ends).
    int noise_generator = 2;
    int number_of_waves = 10;
    // Shared with the copies; `copy`: made from a declared one (POV-Ray's isCopy, whose
    // messages its original gives).
    std::shared_ptr<IsosurfaceGradients> gradients;
    bool copy = false;
};

// parametric { function { X } function { Y } function { Z } <u1, v1>, <u2, v2>
// contained_by { box | sphere } max_gradient accuracy precompute N x, y, z }: the surface
// (X, Y, Z)(u, v) over the uv rectangle, met by POV-Ray 3.7's subdivision of that
// rectangle (trace/shapes/parametric.h). No inside (POV-Ray's PATCH_OBJECT).
struct ParametricPrecompute {
    int depth = 1;  // the tree has 2^depth entries (index 1 the root)
    bool axis[3] = {false, false, false};  // x, y, z precomputed
    std::vector<Real> low[3], high[3];  // per axis, by sector index (core/parametric.h)
};
struct Parametric {
    std::shared_ptr<const FunctionProgram> functions[3];  // of u, v (x, y)
    Real umin = 0, vmin = 0, umax = 1, vmax = 1;
    bool sphere_container = false;
    Point3 corner1{-1, -1, -1}, corner2{1, 1, 1};  // the box (sorted per axis)
    Point3 centre{0, 0, 0};
    Real radius = 1;
    Real accuracy = 0.001, max_gradient = 1;
    std::shared_ptr<const ParametricPrecompute> precompute;  // null: none
    // The global settings the functions' patterns and f_noise3d read (set when the
    // parse ends).
    int noise_generator = 2;
    int number_of_waves = 10;
};

struct Object;
namespace trace {
struct CsgChildIndex;  // trace/csg_children.h
}
enum class CsgKind : uint8_t { Union, Merge, Intersection, Difference };
struct Light;

// POV-Ray's on/off switches that also remember whether they were given: an object's
// `refraction on` or a light's turns photon refraction on unless the other says off.
enum class PhotonSwitch : uint8_t { Unset, On, Off };

// An object's `photons { target [spacing_multiplier] refraction reflection collect
// pass_through }` (POV-Ray 3.7's PH_TARGET, PH_RFR/RFL_ON/OFF, PH_IGNORE_PHOTONS and
// PH_PASSTHRU flags, Ph_Density).
struct ObjectPhotons {
    bool target = false;
    float spacing_multiplier = 1;  // Ph_Density
    PhotonSwitch refraction = PhotonSwitch::Unset, reflection = PhotonSwitch::Unset;
    bool collect = true;
    bool pass_through = false;
};

struct Csg {
    CsgKind kind = CsgKind::Union;
    std::vector<Object> children;
    // Light sources written inside the CSG move with it; the parser moves them to
    // Scene::lights when the object is placed in the scene.
    std::vector<Light> lights;
    // A `light_group { }` (a union): its `lights` light only its objects (see
    // Object::light_group), and with global_lights off the scene's other lights do not.
    bool light_group = false;
    bool global_lights = false;
    // intersection/difference only: a surface without a texture of its own takes the
    // textures of the other children it lies inside (POV-Ray's CUTAWAY_TEXTURES_FLAG).
    bool cutaway_textures = false;
    // The CSG's box as POV-Ray keeps it (lower-left corner and lengths in single
    // precision): joined from the children's boxes when the CSG is closed (a text: from
    // its glyphs' after layout), then moved as a box by every transform, never rebuilt
    // from the children (a turned union's box is the turned box's box). min_extent,
    // max_extent and POV-Ray's bounding tests read it. Unset when the parse had no
    // ObjectQueries (the box is then joined from the children when asked).
    struct PovBox {
        float lo[3], len[3];
    };
    std::optional<PovBox> pov_box;
    // The tracer's index of the children when they are many (set when the scene is
    // prepared).
    DerivedSlot<trace::CsgChildIndex> child_index;
};

using ShapeData =
    std::variant<Sphere, Box, Plane, Cylinder, Cone, Torus, Disc, Triangle,
                 SmoothTriangle, Polygon, Mesh, Superellipsoid, Ovus, Sor, Lathe, Prism,
                 BicubicPatch, JuliaFractal, Glyph, HeightField, SphereSweep, Poly,
                 Quadric, Blob, Isosurface, Parametric, Csg>;

struct Object {
    ShapeData shape;
    CompactTransform transform;  // object space -> world
    // Empty means "no texture given": the renderer uses the default texture.
    LayeredTexture texture;
    // Rarely given, so on the heap (8 bytes each while unset; see HeapValue).
    HeapValue<LayeredTexture> interior_texture;
    HeapOptional<Interior> interior;
    bool inverse = false;
    bool hollow = false;
    bool hollow_given = false;  // `hollow` was written on it (a CSG's then leaves it)
    bool no_shadow = false, no_image = false, no_reflection = false;
    bool no_radiosity = false;  // radiosity sample rays pass through it
    // radiosity { importance } (<= 0: the scene's default importance).
    float radiosity_importance = 0;
    bool double_illuminate = false;
    // `uv_mapping` on the object (POV-Ray's UV_FLAG): its textures are evaluated at the
    // hit's surface coordinates (u, v, 0), and its transforms do not move them.
    bool uv_mapping = false;
    // Light groups (POV-Ray 3.7's LLights and NO_GLOBAL_LIGHTS_FLAG), set on the leaves
    // when the object is placed: the lights of Scene::lights whose Light::light_group
    // equals this (0: none) light it, and the lights of no group light it only when
    // `global_lights` (the outermost enclosing light group's setting).
    bool global_lights = true;
    uint32_t light_group = 0;
    // The object's `photons { }` block (POV-Ray 3.7's PH_* flags), brought down to the
    // leaves when the object is placed (trace/photon_map.h reads the leaves' flags).
    ObjectPhotons photons;
    // `split_union off` on a union: POV-Ray links it to the scene whole, not child by
    // child (which keeps its children's bounded_by, see pov_splits_union()).
    bool split_union = true;
    // clipped_by { bounded_by } or bounded_by { clipped_by }: the two lists are one, as
    // in POV-Ray (no more bounds or clips may be added then).
    bool bounds_are_clips = false;
    HeapValue<std::vector<Object>> clipped_by;
    // A ray that misses every one of these (and starts outside them) skips the object,
    // where POV-Ray keeps the bound: see pov_keeps_bound(). Their boxes also shrink the
    // object's bounding box (trace/pov_bounds.h).
    HeapValue<std::vector<Object>> bounded_by;
    SourceLoc loc;
};

// POV-Ray links a union to the scene child by child (Link_To_Frame), recursively, when it
// is a plain union: not a merge, not inverse, not clipped or bounded, split_union not
// off.
inline bool pov_splits_union(const Object& o) {
    const Csg* csg = std::get_if<Csg>(&o.shape);
    return csg && csg->kind == CsgKind::Union && !o.inverse && o.clipped_by.empty() &&
           o.bounded_by.empty() && o.split_union;
}

// Whether an object linked to the scene keeps its bounded_by (Link_To_Frame with
// Remove_Bounds on, POV-Ray's default): CSG objects and polys do, and a quadric whose
// box did not come from its coefficients; another shape's bound is removed as
// unnecessary. CSG children always keep theirs.
inline bool pov_keeps_bound(const Object& frame_object) {
    if (frame_object.bounded_by.empty()) return false;
    if (const Quadric* q = std::get_if<Quadric>(&frame_object.shape))
        return !q->automatic_bounds;
    return std::holds_alternative<Csg>(frame_object.shape) ||
           std::holds_alternative<Poly>(frame_object.shape);
}

// ---------------------------------------------------------------- lights, camera,
// settings

struct AreaLight {
    Vector3 axis1, axis2;
    int size1 = 1, size2 = 1;
    int adaptive = 100;  // POV-Ray's default when `adaptive` is absent: the full grid
    bool jitter = false, circular = false, orient = false;
    // Each sample lights the surface from its own position (diffuse and highlights), not
    // only its shadow ray: POV-Ray 3.7's area_illumination.
    bool illumination = false;
};

struct Light {
    enum class Kind : uint8_t { Point, Spot, Cylinder, Parallel } kind = Kind::Point;
    // Objects placed before this light in the whole scene (those a filtered parse left
    // out too): where POV-Ray's object list holds it (its looks_like object takes part
    // in POV-Ray's test order there).
    uint32_t objects_before = 0;
    Point3 location;
    Rgb colour{1.0f};
    Point3 point_at{0, 0, 1};
    Real radius = 30, falloff = 45, tightness = 0;  // spot/cylinder (degrees)
    Real fade_distance = 0, fade_power = 0;
    bool shadowless = false;
    // A parallel spotlight: light from point_at's direction at full strength, only in
    // front of the light (a parallel point light is Kind::Parallel).
    bool parallel = false;
    bool media_interaction = true, media_attenuation = false;
    // 0: a global light; else the light group (numbered when placed in the scene) whose
    // objects alone it lights (Object::light_group).
    uint32_t light_group = 0;
    std::optional<AreaLight> area;
    std::vector<Object> looks_like;  // rendered as an object with no shadow
    // `projected_through { }`: the light reaches a point only through this object, which
    // is not part of the scene (trace/light_masks.h); moved by the light's transforms
    // written after it. Shared between copies of the light (copied when moved).
    std::shared_ptr<const Object> projected_through;
    // The light's `photons { refraction reflection }` (its PH_RFR/RFL flags).
    PhotonSwitch photon_refraction = PhotonSwitch::Unset;
    PhotonSwitch photon_reflection = PhotonSwitch::Unset;
    // `photons { area_light }`: an area light shoots photons from each point of its grid
    // (else from its centre).
    bool photon_area_light = false;
    SourceLoc loc;
};

struct MeshCamera;  // core/mesh_camera.h

struct Camera {
    enum class Kind : uint8_t {
        Perspective,
        Orthographic,
        Fisheye,
        UltraWideAngle,
        Panoramic,
        Cylinder1,
        Cylinder2,
        Cylinder3,
        Cylinder4,  // `cylinder N`
        Omnimax,
        Spherical,
        Mesh  // `mesh_camera { }`: rays from the faces of meshes (`mesh`)
    } kind = Kind::Perspective;
    std::shared_ptr<const MeshCamera> mesh;
    // Final vectors after look_at, angle, sky and transforms have been applied.
    Point3 location{0, 0, 0};
    Vector3 direction{0, 0, 1};
    Vector3 right{1.33, 0, 0};
    Vector3 up{0, 1, 0};
    Real angle = 90;  // degrees; the field of view of the non-projective kinds
    // The spherical camera's fields of view (degrees), across and up.
    Real h_angle = 360, v_angle = 180;
    // `normal { }`: perturbs the primary rays' directions, the pattern evaluated at the
    // camera's image coordinates (not moved with the camera). The scene's final
    // noise_generator and number_of_waves go with it, as its patterns read them.
    HeapOptional<Normal> normal;
    int normal_noise_generator = 2, normal_number_of_waves = 10;
    // Focal blur (on with an aperture and blur_samples): each camera sample averages
    // rays from points of the aperture aimed at the focal plane, `focal_distance` from
    // the location along `direction`, stopping early by confidence and variance.
    Real aperture = 0, focal_distance = 1;
    int blur_samples = 0, blur_samples_min = 0;
    Real confidence = 0.9, variance = 1.0 / 10000;
    HeapOptional<Pigment> bokeh;  // the aperture's shape (absent: a disc)
    SourceLoc loc;
};

struct Fog {
    int type = 1;  // 1 constant, 2 ground fog
    Real distance = 0;
    Colour colour;
    // Turbulence thins the fog along each ray (POV-Ray's fog Turb): present once any of
    // turbulence/octaves/omega/lambda is given.
    bool turbulent = false;
    Vector3 turbulence{0, 0, 0};
    int octaves = 6;
    Real omega = 0.5, lambda = 2.0;
    Real turb_depth = 0.5, offset = 0, alt = 0;
    Vector3 up{0, 1, 0};
    std::vector<Warp> warps;
    Transform transform;
};

// `rainbow { }` (POV-Ray 3.7's RAINBOW): a colour band at `angle` (radians, as all
// angles here) from the antisolar direction, `width` wide, looked up in `pigment` (its
// colour map along x from 0 to 1), fading in with distance; `arc_angle` limits it around
// `up`, fading over falloff_angle to arc_angle. `jitter` blurs the band at random.
struct Rainbow {
    Vector3 antisolar{0, 0, 1};           // unit
    Vector3 up{0, 1, 0}, right{1, 0, 0};  // unit, perpendicular to antisolar
    Real angle = 0, width = 0, distance = 0, jitter = 0;
    Real arc_angle = kPi, falloff_angle = kPi, falloff_width = 0;
    HeapOptional<Pigment> pigment;
};

struct SkySphere {
    std::vector<Pigment> pigments;  // layered, first on top
    Rgb emission{1.0f};             // scales the pigments' colour
    Transform transform;
};

// POV-Ray 3.7's gamma modes (its gammaMode), decided by #version and assumed_gamma as
// the parse goes: how image files are decoded while parsing and whether the output is
// encoded at all.
enum class GammaMode : uint8_t {
    None,       // no assumed_gamma, effective version below 3.7: no gamma handling
    Assumed36,  // assumed_gamma given while the effective version was below 3.7
    Assumed37,  // assumed_gamma given in a 3.7 scene
    Implied37,  // a 3.7 scene without assumed_gamma: working gamma 1.0
};

// global_settings { photons { } } (POV-Ray 3.7's ScenePhotonSettings with the values its
// parser sets when the block is given). trace/photon_map.h builds the map.
struct PhotonSettings {
    float spacing = 1;  // surfaceSeparation
    int count = 0;      // surfaceCount: 0 unless `count` chose the spacing
    int gather_min = 20, gather_max = 100;
    float jitter = 0.4f;
    float autostop = 0.5f;
    float expand_tolerance = 0.2f;
    int expand_min = 35;
    int max_trace_level = -1;  // < 0: global_settings' max_trace_level
    float adc_bailout = -1;    // < 0: global_settings' adc_bailout
    float radius = -1;         // gather radius; <= 0: estimated from the map
    float radius_multiplier = 1;
    // Media photons (`media steps[, factor]`; `radius`'s third and fourth values): at
    // most `media_steps` photons stored per media interval a photon crosses, spaced
    // `media_spacing_factor` times the surface spacing; none when 0.
    int media_steps = 0;
    float media_spacing_factor = 1;
    float media_radius = -1;  // <= 0: estimated from the media map
    float media_radius_multiplier = 1;
    SourceLoc loc;  // the `photons` keyword
};

// global_settings { radiosity { } } (POV-Ray 3.7's SceneRadiositySettings with its
// defaults; the block turns radiosity on, from +Q9). trace/radiosity/ renders it.
struct RadiositySettings {
    double brightness = 1;
    int count = 35;
    int direction_pool = 1600;  // count's second value: the sample direction set's size
    double error_bound = 1.8;
    double gray_threshold = 0;
    double low_error_factor = 0.5;
    double minimum_reuse = 0.015;
    double maximum_reuse = 0.2;
    int nearest_count = 5;
    int nearest_count_pretrace = 0;  // nearest_count's second value (adaptive pretrace)
    int recursion_limit = 2;
    double max_sample = -1;  // <= 0: no limit
    double adc_bailout = 0.01;
    bool normal = false, media = false, subsurface = false;
    double pretrace_start = 0.08, pretrace_end = 0.04;
    bool always_sample = false;
    float default_importance = 1;  // #default { radiosity { importance } }
    SourceLoc loc;                 // the `radiosity` keyword
};

// global_settings { subsurface { samples, radiosity } }: the block turns subsurface
// light transport on for the finishes that have it (from +Q9).
struct SubsurfaceSettings {
    int samples_diffuse = 50, samples_single = 50;
    bool radiosity = false;
    SourceLoc loc;  // the `subsurface` keyword
};

struct GlobalSettings {
    int max_trace_level = 5;
    float adc_bailout = 1.0f / 255.0f;
    Rgb ambient_light{1.0f};
    std::optional<GammaCurve> assumed_gamma;  // absent: Scene::gamma_mode decides
    // Absent from the scene, it follows the final #version: 1 below 3.5, else 2.
    int noise_generator = 2;
    int max_intersections = 64;
    Rgb irid_wavelength{
        0.70f, 0.52f,
        0.48f};  // POV-Ray 3.7's (not the 0.25, 0.18, 0.14 its documentation gives)
    int number_of_waves = 10;
    // A photons block with gather_max > 0 (POV-Ray's photonsEnabled before +Q).
    std::optional<PhotonSettings> photons;
    // A radiosity block (POV-Ray's radiosityEnabled before +Q).
    std::optional<RadiositySettings> radiosity;
    std::optional<SubsurfaceSettings> subsurface;
    double mm_per_unit = 10;  // millimetres in a scene unit (subsurface's lengths)
};

// What an interior stack needs of a node of an object the parse left out (see
// Scene::left_out_nodes): a ray that entered the object in another process may still
// count as inside it here, where the object is not (POV-Ray's interior list is not
// geometry: a ray leaving two glass objects through a face they share crosses one of
// the surfaces only, and a media sample on a container's surface sends shadow rays that
// start outside the container, inside its interior).
struct LeftOutNode {
    uint32_t node = 0;    // its number in the whole scene's walk (object_first_node)
    bool hollow = false;  // media and fog fill it (its interior's flag when it has one)
    // Null: a default interior (interior_is_default). Held by Scene::left_out_interiors,
    // one for all the nodes of a tree that share it.
    const Interior* interior = nullptr;
};

// Everything a render needs besides the output settings.
struct Scene {
    std::vector<std::string>
        files;  // sources (SourceLoc::file indexes these), then image files
    Camera camera;
    std::vector<Object> objects;
    std::vector<Light> lights;
    Colour background{Rgb{0.0f}, 0.0f, 1.0f};  // default: black, fully transparent in +UA
    // The background statement came while the effective version was below 3.7: POV-Ray
    // then drops its filter and takes its transmit from +UA alone.
    bool background_legacy = false;
    std::optional<SkySphere> sky_sphere;
    std::vector<Fog> fogs;
    std::vector<Rainbow> rainbows;        // applied in reverse order of appearance
    std::vector<Media> atmosphere_media;  // scene-level `media { }`
    GlobalSettings settings;
    // Set when the parse left objects out (ParseOptions::keep_object: a black-box worker
    // keeps only what overlaps its boxes). Objects and their CSG children are numbered
    // in one pre-order walk of the whole scene's objects, then the lights' looks_like
    // objects; processes holding different parts of a scene must agree on those numbers
    // (interior stacks on the wire), so each kept object keeps the number of its first
    // node in the whole scene's walk, and the walk's total is kept too.
    std::vector<uint32_t> object_first_node;
    uint32_t object_nodes_total = 0;
    size_t objects_left_out = 0;
    bool objects_filtered() const {
        return objects_left_out > 0 || !object_first_node.empty();
    }
    // The left-out objects' nodes (CSG children included) whose interior is not a
    // default one or that are hollow, by ascending node number: an interior stack entry
    // naming one of them (wire/items.h, ObjectNumbers) gets its ior, media and hollow
    // flag without the object's shape or textures. Any other left-out node has a default
    // interior and is not hollow.
    std::vector<LeftOutNode> left_out_nodes;
    std::vector<std::shared_ptr<const Interior>> left_out_interiors;
    // Records what interior stacks need of `o`, left out, whose first node is
    // `first_node` (every node after the last one recorded).
    void leave_out(const Object& o, uint32_t first_node);
    // The record of left-out node `node`; null: a default interior, not hollow.
    const LeftOutNode* left_out_node(uint32_t node) const;
    // POV-Ray's effective language version at the end of parsing, times 100 (e.g. 362,
    // 370): the #version in force then, or 362 for a scene that never set one (+MV sets
    // one too). What the `version` identifier reads is the parser's business.
    int language_version = 362;
    bool version_set = false;
    GammaMode gamma_mode = GammaMode::None;
    // Whether output colours are gamma-encoded (3.7 rules) or written raw (legacy).
    bool gamma_handling() const { return gamma_mode != GammaMode::None; }
    bool assumed_gamma_given() const { return settings.assumed_gamma.has_value(); }
};

// Nodes of an object's tree: the object and, for CSG, its children's trees.
inline size_t object_node_count(const Object& o) {
    size_t n = 1;
    if (auto c = std::get_if<Csg>(&o.shape)) {
        for (const Object& ch : c->children) n += object_node_count(ch);
    }
    return n;
}

// The first media that scatters light (atmosphere first, then the objects' interiors),
// or null: such media light their samples with shadow rays.
const Media* first_scattering_media(const Scene& scene);

// `whole` with only the objects at the ascending indices `keep`, numbered as the parser
// numbers a parse that left the others out (ParseOptions::keep_object), so a process that
// got the whole parsed scene (a forked black-box worker) agrees with one that parsed only
// its part. Everything except the objects is moved out of `whole`; the kept objects are
// copied (a forked worker's textures and the rest stay on the pages it shares with its
// parent). `whole`, which must not be filtered already, keeps its full object list,
// untouched, and nothing else.
Scene take_scene_keeping(Scene&& whole, const std::vector<uint32_t>& keep);

}  // namespace povwall
