// Values of the scene language: what identifiers hold and expressions produce.
#pragma once

#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "core/scene.h"
#include "core/spline.h"

namespace povwall::parser {

// Floats, vectors (2-5 components) and colours share one representation, as in POV-Ray,
// where a colour is a 5-component vector (r, g, b, filter, transmit).
struct Numeric {
    int size = 1;  // 1 float, 2..5 vector
    bool colour = false;
    double c[5] = {0, 0, 0, 0, 0};

    static Numeric scalar(double v) {
        Numeric n;
        n.c[0] = v;
        return n;
    }
    static Numeric vector(const Vector3& v) {
        Numeric n;
        n.size = 3;
        n.c[0] = v.x;
        n.c[1] = v.y;
        n.c[2] = v.z;
        return n;
    }
    Vector3 vec3() const {
        if (size == 1) return Vector3(c[0]);
        return {c[0], c[1], size > 2 ? c[2] : 0.0};
    }
};

struct Macro;
struct ArrayValue;
// A declaration whose right-hand side uses a feature povwall lacks: harmless until used.
struct UnsupportedValue {
    std::string feature;
};
struct CameraSpec;
struct UserFile;
struct Material {
    LayeredTexture texture;
    LayeredTexture interior_texture;
    HeapOptional<Interior> interior;
};

using Value = std::variant<
    std::monostate, Numeric, std::string, std::shared_ptr<Object>,
    std::shared_ptr<LayeredTexture>, std::shared_ptr<Pigment>, std::shared_ptr<Finish>,
    std::shared_ptr<Normal>, std::shared_ptr<Interior>, std::shared_ptr<CameraSpec>,
    std::shared_ptr<Light>, std::shared_ptr<ArrayValue>, std::shared_ptr<Transform>,
    std::shared_ptr<Macro>, std::shared_ptr<Material>, std::shared_ptr<ColourMap>,
    std::shared_ptr<SkySphere>, std::shared_ptr<Fog>, std::shared_ptr<UnsupportedValue>,
    std::shared_ptr<UserFile>, std::shared_ptr<const Spline>,
    std::shared_ptr<const FunctionProgram>, std::shared_ptr<Media>>;

struct ArrayValue {
    std::vector<int> dims;
    std::vector<Value> items;  // row-major; monostate = not yet assigned
};

struct Macro {
    std::string name;
    int file;
    size_t body_begin, body_end;  // token indices in that file; body_end is the #end
    std::vector<std::string> params;
};

// A file opened by #fopen (file_io.cpp). A file read is lexed like a scene file, so its
// values come from tokens and an error in it is located in it; POV-Ray reads data files
// with its scene tokenizer too.
struct UserFile {
    std::string name;  // as the scene wrote it
    bool reading = false;
    int file = -1;        // reading: the SourceManager index of its tokens
    size_t pos = 0;       // reading: the next token
    bool at_end = false;  // reading: the last token asked for was the end of the file
    std::unique_ptr<std::ostream> out;  // writing; null: the writes are discarded
};

// Camera as written: kept raw so that `camera { ID modifiers }` can be re-evaluated.
struct CameraSpec {
    Camera::Kind kind = Camera::Kind::Perspective;
    Vector3 location{0, 0, 0}, direction{0, 0, 1}, right{1.33, 0, 0}, up{0, 1, 0};
    Vector3 sky{0, 1, 0}, look_at{0, 0, 1};
    bool has_look_at = false, has_angle = false, has_up = false, has_right = false;
    // Read while the language version was below 3.5: every item was applied where it
    // stood (POV-Ray's old-style camera), so the vectors above are final and `transform`
    // is unused.
    bool legacy = false;
    double angle = 90;
    double h_angle = 360, v_angle = 180;  // spherical
    HeapOptional<Normal> normal;
    // Focal blur. focal_distance: set by a legacy camera's focal_point where it stood,
    // else from the 3.5+ focal_point; negative until then (finish_camera decides).
    double aperture = 0, confidence = 0.9, variance = 1.0 / 10000, focal_distance = -1;
    int blur_samples = 0, blur_samples_min = 0;
    bool has_focal_point = false;
    Vector3 focal_point{0, 0, 1};
    HeapOptional<Pigment> bokeh;
    std::shared_ptr<const MeshCamera> mesh;  // mesh_camera
    // A legacy camera's length of `direction` as its angle and look_at left it (POV-Ray's
    // Direction_Length: the focal distance when none is given).
    double legacy_direction_length = 1;
    bool parsed = false;  // a camera block made it (not the default camera)
    Transform transform;
    SourceLoc loc;
    uint32_t offset = 0;  // of the camera's '{', for diagnostics
};

const char* type_name(const Value& v);

}  // namespace povwall::parser
