// The interpreter: a single pass over the token stream that runs directives as it meets
// them (so they may appear anywhere, as in POV-Ray) and builds the scene as it goes.
#pragma once

#include <chrono>
#include <functional>
#include <string>
#include <unordered_map>
#include <vector>

#include "parser/expression_program.h"
#include "parser/function_image.h"
#include "parser/parser.h"
#include "parser/source.h"
#include "parser/value.h"

namespace povwall::parser {

// The words POV-Ray 3.7 runs as directives after '#' (a '#' before any other word is
// dropped, as POV-Ray's Parse_Directive does).
bool is_directive_name(std::string_view word);
// `color`/`colour` and POV-Ray's colour keys (rgb ... srgbft, red, green, blue, filter,
// transmit, alpha): the words a colour can start with.
bool is_colour_keyword(std::string_view word);

class TrueTypeFont;
struct ImageFileType;

// POV-Ray's Recompute_BBox: the box's corners through `t`, their bounding box clipped at
// +-1e10 and kept in single precision.
void move_pov_box(Csg::PovBox& box, const Transform& t);

// Limits that turn runaway scenes into located errors instead of exhausted memory or a
// hang.
constexpr int kMaxIncludeDepth =
    64;  // POV-Ray allows 32 open files; machine scenes stay lower
constexpr int kMaxMacroDepth =
    1000;  // recursion guard (POV-Ray's symbol table limit is 100)
constexpr size_t kMaxArrayItems = 1u << 28;
// Expressions, objects and patterns nested inside each other; far beyond any real scene,
// well within the stack (sanitizer builds included).
constexpr int kMaxNesting = 256;

// (int)v truncated toward zero, saturating at int's range; NaN gives 0.
inline int saturating_int(double v) {
    if (!(v == v)) return 0;
    if (v >= 2147483647.0) return 2147483647;
    if (v <= -2147483648.0) return -2147483647 - 1;
    return int(v);
}

// Composes `t` into every pattern transform of the layers (textures move with objects).
void transform_textures(LayeredTexture& layers, const Transform& t);
void transform_pigment(Pigment& p, const Transform& t);
void transform_interior(HeapOptional<Interior>& in, const Transform& t);

// Which of POV-Ray's transform methods a keyword calls on an object: a sphere_sweep
// moves its spheres for translate, rotate and a uniform scale (until it keeps a
// matrix) and keeps a matrix for anything else.
struct TransformStep {
    enum class Kind : uint8_t { Translate, Rotate, Scale, Matrix };
    Kind kind = Kind::Matrix;
    Vector3 amount{0, 0, 0};  // the keyword's vector
};

class Interpreter {
  public:
    Interpreter(const ParseOptions& options, SourceManager& sources);
    Scene run(int root_file);

    // ---- token stream (tokens.cpp)
    // After `light_source`: whether its braces start with a declared object that is no
    // light (POV-Ray's Parse_Object_Id then reads it as `object { Id ... }`); reads
    // nothing.
    bool light_block_names_object();
    const Token& peek() {
        if (pushback_.empty()) [[unlikely]]
            fill_pushback();
        return pushback_.back();
    }
    Token next();
    void unget(const Token& t);
    bool accept_punct(char c);
    bool accept_word(std::string_view w);
    bool accept_raw_word(std::string_view w);
    bool accept_raw_punct(char c);
    bool raw_next_is_punct(char c);  // without running a directive behind it
    bool accept_semicolon();
    void expect_punct(char c, std::string_view what = {});
    // The message "'c' <what>'<name>'" is only built when the token is wrong.
    void expect_punct(char c, std::string_view what, std::string_view name);
    bool is_punct(const Token& t, char c) const {
        return t.kind == TokenKind::Punct && t.length == 1 && t.text[0] == c;
    }
    bool is_word(const Token& t, std::string_view w) const {
        return t.kind == TokenKind::Word && t.text == w;
    }
    [[noreturn]] void error(const Token& at, const std::string& message);
    // A located `warning:` diagnostic on the messages stream; parsing goes on.
    void warn(const Token& at, const std::string& message) {
        if (options_.messages)
            *options_.messages << format_diagnostic(sources_, at, "warning", message)
                               << "\n";
    }
    // POV-Ray's degenerate triangle: (P1 - P2) x (P3 - P2) of length exactly 0
    // (Triangle::Compute_Triangle, Mesh::Degenerate). A tiny triangle is not degenerate.
    static bool degenerate_corners(const Point3 p[3]) {
        return length(cross(p[0] - p[1], p[2] - p[1])) == 0;
    }
    // `deferrable`: see ParseError::deferrable().
    [[noreturn]] void unsupported(const Token& at, std::string_view feature,
                                  bool deferrable = true);
    [[noreturn]] void expected(std::string_view what, const Token& found);
    std::string describe(const Token& t) const;

    // ---- symbols
    const Value* lookup(std::string_view name) const;
    const Value* lookup(const Token& t) const {
        if (!t.sym) return lookup(t.text);
        // Most words are keywords, never bound: answered here, without a call.
        if (t.sym >= bound_.size() || !bound_[t.sym]) return nullptr;
        return lookup_symbol(t.sym);
    }
    const Value* lookup_symbol(uint32_t sym) const;
    bool is_bound(uint32_t sym) const { return sym < bound_.size() && bound_[sym]; }
    void declare(const std::string& name, Value v, bool local, const Token& at) {
        declare_symbol(sources_.intern(name), std::move(v), local, at);
    }
    // `visible_scopes`: how many scopes (from the global one) #declare may find an
    // existing identifier in; the rest belong to macros its right-hand side called.
    void declare_symbol(uint32_t sym, Value v, bool local, const Token& at,
                        size_t visible_scopes = SIZE_MAX);

    // ---- expressions (expressions.cpp)
    // `hold_directives`: a directive or macro call where an operator could follow ends
    // the value unrun (the value of a #declare or #version; see peek_after_operand).
    Value parse_expression_value(bool hold_directives = false);  // float ... or string
    // Same without comparisons: POV-Ray's Parse_RValue (array items, macro arguments).
    Value parse_value_additive();
    // POV-Ray's Parse_Float/Vector level
    Numeric parse_numeric(bool no_gt = false, bool hold_directives = false);
    Numeric parse_express(bool hold_directives = false);  // full (Parse_Express)
    // The next token where an operator may follow an operand. With `hold_directives` a
    // directive or macro call there is returned without running it and left in the
    // stream (POV-Ray's Ok_To_Declare = false).
    const Token& peek_after_operand(bool hold_directives);
    // Reports a non-numeric value where Parse_Express wanted one.
    [[noreturn]] void not_numeric(const Value& v, const Token& at);
    double parse_float();
    // A float POV-Ray stores in single precision (a SNGL field: a pattern's frequency,
    // phase, wave exponent, agate_turb, quilted controls, turbulence omega and lambda, a
    // normal's amount and accuracy), rounded as it stores it.
    double parse_single();
    // A float read as POV-Ray reads counts and indices, truncated toward zero; values
    // past int's range (or NaN) saturate instead of being undefined.
    int parse_int() { return saturating_int(parse_float()); }
    // A directive's parenthesised condition; reads nothing past the ')' so that the
    // tokens after it are not consumed before the directive decides whether to skip them.
    double parse_condition();
    Vector3 parse_vector();  // float promoted to <f,f,f>
    std::string parse_string();
    // Colour keyword forms, rgb, identifiers; `hold_directives` as parse_express.
    // `any_vector`: any vector expression may be the colour, as where POV-Ray's
    // Parse_Colour is called directly; a colour map entry's (after CASE_COLOUR) may not
    // start with x, y, z, u, v, a vector function or a unary '+' or '!'.
    Numeric parse_colour(bool hold_directives = false, bool any_vector = true);
    Colour parse_colour_value(bool any_vector = true);
    bool parse_bool_opt();
    bool starts_float(const Token& t);  // can `t` begin a float expression?
    // Can `t` begin a float, vector or colour expression (POV-Ray's CASE_EXPRESS)?
    bool starts_expression(const Token& t);
    void require_operand(std::string_view what);
    float parse_map_value(
        bool average);  // the value of a *_map entry  // error if the block ends here //
                        // optional boolean after a flag keyword

    // ---- scene items (objects.cpp, textures.cpp, scene_items.cpp)
    bool try_parse_object(const Token& t, Object& out);
    // POV-Ray's Parse_Object: a declared object named bare (a copy of it), or an object.
    bool try_parse_object_or_identifier(const Token& t, Object& out);
    void parse_object_modifiers(Object& obj);
    bool try_object_modifier(Object& obj, const Token& t);
    bool try_transform(const Token& t, Transform& out, TransformStep* step = nullptr);
    Transform parse_transform_block();
    void apply_transform(Object& obj, const Transform& t, const TransformStep& step = {});
    // apply_transform's work on one node and its children (the julia_fractal rule is
    // settled once for the whole object).
    void transform_node(Object& obj, const Transform& t, const TransformStep& step);
    void transform_light(Light& l, const Transform& t, const TransformStep& step = {});
    // Moves light sources written inside CSG objects into the scene.
    void collect_lights(Object& obj);
    LayeredTexture parse_texture_block();  // after 'texture'
    void parse_texture_body(LayeredTexture& layers, char terminator);
    // The texture of language versions below 3.0, pigment, normal and finish items
    // written straight in it (POV-Ray's Parse_Vers1_Texture; parser/texture_vers1.cpp).
    void parse_vers1_texture_body(LayeredTexture& layers, char terminator);
    void parse_tiles(const Token& keyword, LayeredTexture& layers);  // after 'tiles'
    void parse_texture_transforms(LayeredTexture& layers, char terminator);
    // After the keyword: a new part starts from the default texture's (a fresh interior);
    // the *_into forms edit the part a texture, object or #default holds, so a repeated
    // block continues from the earlier one (notes/parser-rules.md §2).
    Pigment parse_pigment_block();  // after 'pigment'
    void parse_pigment_into(Pigment& p);
    void parse_pigment_body(Pigment& p, char terminator);
    Finish parse_finish_block();  // after 'finish'
    void parse_finish_into(Finish& f);
    void parse_finish_into(SharedValue<Finish>& f);
    SharedValue<Finish> shared_finish(const Finish& f);
    Normal parse_normal_block();  // after 'normal'
    void parse_normal_into(HeapOptional<Normal>& n);
    void parse_normal_body(Normal& n, char terminator);
    Interior parse_interior_block();  // after 'interior'
    void parse_interior_into(Interior& in);
    void parse_interior_into(HeapOptional<Interior>& in);
    // Puts `layers` on top of an object's (or a declaration's) texture, refusing to
    // layer over or with a patterned texture as POV-Ray's Link_Textures does.
    void link_textures(LayeredTexture& onto, LayeredTexture&& layers, const Token& at);
    ColourMap parse_colour_map_block();  // after 'color_map'
    // A pattern keyword and what follows it; the patterns POV-Ray starts at frequency 0
    // (no wrapping: the block patterns, object, quilted, image_pattern) get it here.
    bool try_pattern_keyword(const Token& t, PatternSpec& spec);
    bool try_pattern_keyword_kind(const Token& t, PatternSpec& spec);
    PatternSpec::Slope parse_slope();  // after 'slope' (the pattern)
    // After `object` as a pattern: `{ OBJECT [transforms]` up to its list entries, which
    // the caller reads (as checker's) before the closing '}' (parser/pattern_object.cpp).
    void parse_object_pattern(const Token& keyword, PatternSpec& spec);
    // After `material_map` in a texture: the image and its textures (texture_maps.cpp).
    void parse_material_map(const Token& keyword, Texture& into);
    // A located error where a pigment that uv_mapping, which needs a surface hit, is
    // used where there is none (a pigment function, a media density).
    void refuse_uv_mapping(const Pigment& p, const Token& at, std::string_view where);
    bool try_pattern_keyword(const Token& t, HeapValue<PatternSpec>& spec);
    // An image file named in a scene: `[TYPE] "name"` (POV-Ray's Parse_Image), its type
    // (from the keyword, else the name's extension, else the output file type) and the
    // file found for it (images.cpp). `height_field` selects the types legal there.
    struct ImageFileRef {
        const ImageFileType* type = nullptr;
        Token type_token;  // the type keyword, else the name
        Token name_token;
        std::string path;
    };
    ImageFileRef parse_image_file_ref(bool height_field);
    // A gamma as assumed_gamma and an image's `gamma` take it: `srgb` or a positive
    // power law's decoding exponent (POV-Ray's Parse_Gamma).
    GammaCurve parse_gamma();
    // After image_map / bump_map (`bump` receives bump_size), image_pattern or
    // material_map (which stops before its first `texture`): the mapping, pixels loaded.
    enum class ImageBlock : uint8_t { ImageMap, BumpMap, ImagePattern, MaterialMap };
    std::shared_ptr<const ImageMapping> parse_image_block(
        const Token& keyword, Normal* bump, ImageBlock block = ImageBlock::ImageMap);
    // The items after an image block's file (or function): once, interpolate, map_type,
    // repeat, filter/transmit, ...; `pixels` null when the scene is parsed without
    // images.
    void parse_image_options(const Token& keyword, ImageBlock block, Normal* bump,
                             ImageMapping& mapping,
                             const std::shared_ptr<ImagePixels>& pixels, bool has_alpha,
                             bool colour_mapped);
    // After `density_file`: `df3 "name"`, the file found as POV-Ray finds it and read
    // (density_files.cpp; one read per file and parse, shared by every pattern naming
    // it).
    std::shared_ptr<const DensityFile> parse_density_file();
    bool try_pattern_modifier(const Token& t, PatternSpec& spec);
    bool try_pattern_modifier(const Token& t, HeapValue<PatternSpec>& spec);
    // At the end of a block whose pattern is pavement (`at`, the token that ends it):
    // its values checked and reduced as POV-Ray's Parse_Pattern does; others untouched.
    void finish_pavement(PatternSpec& spec, const Token& at);
    void finish_pavement(HeapValue<PatternSpec>& spec, const Token& at) {
        if (spec->kind == PatternKind::Pavement) finish_pavement(spec.edit(), at);
    }
    Light parse_light_block();
    // After `light_group`: its objects and lights as a union marked Csg::light_group,
    // then its transforms and `global_lights` (light_groups.cpp).
    void parse_light_group(const Token& keyword, Object& out);
    // When a placed object's lights join the scene: numbers each light group with lights
    // and objects, and gives every leaf its group and global_lights (POV-Ray's
    // Promote_Local_Lights and Set_CSG_Children_Flag).
    void assign_light_groups(Object& obj);
    // At the end of the parse: light groups whose lights would light media differently
    // from the global lights are refused (light_groups.cpp).
    uint32_t light_groups_ = 0;  // groups numbered so far (Light::light_group)
    // The global photons keyword (photons.cpp).
    std::optional<Token> photons_at_;
    // The global radiosity keyword (radiosity.cpp).
    std::optional<Token> radiosity_at_;
    // The first finish with subsurface (POV-Ray warns that it is experimental).
    std::optional<Token> subsurface_finish_at_;
    void parse_radiosity_settings(const Token& at);
    void parse_subsurface_settings(const Token& keyword);
    void parse_object_radiosity(Object& obj);
    void check_radiosity();
    CameraSpec parse_camera_block();
    // The rest of a camera block read as POV-Ray read it before 3.5, from `c`.
    CameraSpec parse_legacy_camera(CameraSpec c);
    bool parse_focal_blur_item(const Token& t, CameraSpec& c);
    std::shared_ptr<const MeshCamera> parse_mesh_camera(const Token& at);
    Rainbow parse_rainbow(const Token& at);
    void parse_global_settings();
    // photons.cpp
    void parse_photon_settings(const Token& at);
    void parse_light_photons(Light& l);
    void parse_object_photons(Object& obj);
    enum class PhotonPassThroughCause { Target, Refraction, PassThrough };
    void check_photon_pass_through(ObjectPhotons& ph, const Token& at,
                                   PhotonPassThroughCause cause);
    static void inherit_photons(ObjectPhotons& child, const ObjectPhotons& parent);
    Value parse_declared_value(const Token& first);
    bool starts_string(const Token& t) const;  // a string literal, function or identifier
    // A missing ';' after a declared float, vector or colour (`forced`) or after
    // #version: POV-Ray 3.7's error (forced, from #version 3.5 on) or "possible error"
    // (from 3.1).
    void check_semicolon(const Token& at, bool forced);
    Value parse_item_value(const Token& t);
    void parse_array_initializer(ArrayValue& a, size_t dim, size_t base);
    // `spline { ... }` after the keyword, and a call `S(p [, kind])` after `S`.
    std::shared_ptr<const Spline> parse_spline_block();
    Numeric call_spline(const Spline& s);
    // `function [(params)] { ... }` after the keyword, and a call `F(a, ...)` after `F`
    // (functions.cpp).
    std::shared_ptr<const FunctionProgram> parse_function_block(bool inline_form = false);
    Numeric call_function(const Token& name, const FunctionProgram& f);
    Camera finish_camera(const CameraSpec& spec);
    SkySphere parse_sky_sphere();
    Fog parse_fog();
    Media parse_media();            // after the keyword media
    Pigment parse_density_block();  // after the keyword density
    // The function hooks for a call while parsing, told the global settings parsed so
    // far (noise_generator, number_of_waves), as POV-Ray evaluates with them.
    FunctionHooks parse_time_hooks() const;
    void parse_mesh(Object& out);
    void parse_mesh2(Object& out);
    // Shapes with a file of their own (parser/shape_*.cpp); `keyword` locates warnings.
    void parse_prism(Object& out, const Token& keyword);
    void parse_bicubic_patch(Object& out, const Token& keyword);
    void parse_julia_fractal(Object& out, const Token& keyword);
    // The body of each shape after its '{' (parser/shape_<name>.cpp).
    void parse_superellipsoid(Object& out);
    void parse_ovus(const Token& keyword, Object& out);
    void parse_sor(const Token& keyword, Object& out);
    void parse_lathe(Object& out);
    // parser/shape_poly.cpp: cubic (order 3), quartic (4), poly (0: the order is read).
    void parse_poly(Object& out, int order);
    void parse_polynomial(Object& out);
    void parse_quadric(Object& out);
    int parse_poly_order(std::string_view message);
    double parse_poly_coefficient();
    // The clipped poly set-up whose POV-Ray box povwall does not follow.
    void check_algebraic_bounds(const Object& obj, const Token& keyword);
    // A height field's grid as read, built into the shape by finish_height_field after
    // the object's modifiers (POV-Ray's Compute_HField runs then: `hierarchy` counts).
    struct PendingHeightField {
        int width = 0, depth = 0;
        std::vector<uint16_t> heights;  // [z * width + x]
        Real water = 0;                 // 65536 * water_level
    };
    PendingHeightField parse_height_field(Object& out);
    // `W, H { body }` after the word `function` in place of an image file of `keyword`'s
    // block (parser/function_image.cpp).
    FunctionImage parse_function_image(std::string_view keyword);
    // The heights of an image file of type `kind` (rows top first, as stored), as POV-Ray
    // 3.7 takes them from each kind of image; refuses what it cannot reproduce.
    std::vector<uint16_t> height_field_image_heights(const StoredImage& stored,
                                                     std::string_view kind,
                                                     const Token& at, int& width,
                                                     int& depth);
    void finish_height_field(Object& out, PendingHeightField pending);
    void parse_sphere_sweep(Object& out);
    // parser/shape_blob.cpp: the components and threshold (the object's modifiers come
    // after, as for every shape); a component's own modifiers up to its '}'.
    void parse_blob(Object& out);
    void parse_blob_component_modifiers(BlobElement& e, LayeredTexture& tex);
    // parser/shape_isosurface.cpp: the function and the isosurface's own options.
    void parse_isosurface(Object& out, const Token& keyword);
    // `contained_by { box { C1, C2 } | sphere { C, R } }` after its keyword (isosurface
    // and parametric): box corners sorted per axis.
    void parse_contained_by(bool& sphere, Point3& corner1, Point3& corner2,
                            Point3& centre, Real& radius);
    // parser/shape_parametric.cpp: the functions, the uv rectangle and the options.
    void parse_parametric(Object& out, const Token& keyword);
    // At the end of the parse: the global settings every isosurface's and parametric's
    // function reads.
    void settle_isosurfaces();
    // How many of the scene's objects (left-out ones too) hold each mesh's data, counted
    // as they are added and written into every mesh at the end (Mesh::copies).
    void count_mesh_copies(const Object& o);
    void settle_mesh_copies();
    // POV-Ray's UV vector: a float stands for both; 3 or more components are an error.
    ProfilePoint parse_uv_vector();
    int parse_count();
    template <class T>
    void reserve_list(std::vector<T>& list, int count);
    // k-th raw token ahead (End when there is pushback or the frame ends first).
    Token raw_ahead(size_t k) const;
    bool try_plain_vector(Vector3& out, Token* at);
    int new_random_stream(int seed);
    double draw_random(int stream, const Token& at);

    const ParseOptions& options() const { return options_; }
    int language_version() const { return version_; }  // what `version` reads
    int effective_version() const { return version_set_ ? version_ : 362; }
    Texture default_texture() const { return default_texture_; }

  private:
    friend class DirectiveRunner;
    struct Frame {
        int file;
        size_t pos, end;
        enum class Kind { File, Macro } kind;
        size_t scope_depth;  // scopes to restore when the frame ends
        Token call;          // macro call site (for notes)
        // &sources_.file(file).tokens, fixed once lexed: next_raw() reads the next token
        // without walking SourceManager -> SourceFile each time.
        const TokenArray* toks = nullptr;
    };
    struct Cond {
        enum class Kind { If, Else, While, For, Switch, SwitchDone, Macro } kind;
        size_t frame;     // frame depth where it was opened
        size_t pos;       // loop restart position
        std::string var;  // #for variable
        double end = 0, step = 1;
        Token at;
        uint64_t iterations = 0;  // #for runs so far
    };
    struct Binding {
        Value value;
        // Macro parameters passed an identifier alias the caller's variable.
        int ref_scope = -1;
        uint32_t ref_name = 0;
    };
    using Scope = std::unordered_map<uint32_t, Binding>;
    // Inserts (or finds) `sym` in `scope`, remembering that the name has been bound
    // somewhere.
    Binding& bind(Scope& scope, uint32_t sym) {
        if (sym >= bound_.size()) bound_.resize(sym + 1024, 0);
        bound_[sym] = 1;
        return scope[sym];
    }

    Token next_raw();
    // The next raw token, left unread: finished macro bodies and files on the way are
    // left (their frames and scopes end) as next_raw() leaves them, nothing is run.
    Token peek_raw_past_frame_ends();
    void fill_pushback();  // peek()'s slow path, out of line so that peek() inlines
    // `A[i][j]` read as one token standing for the element (see next()).
    Token subscript_token(const Token& name, const ArrayValue& array);
    // A token standing for `value` under `label`, a name no scene can spell, bound in the
    // global scope from a small rotating pool (array elements, and a macro's local that
    // its call's argument read after the macro ended).
    Token hidden_name_token(const Token& like, const std::string& label,
                            const Value& value, uint32_t end_offset);
    void skip_declaration_rest();
    void run_directive(const Token& t);
    void directive_if(const Token& t, bool taken_value);
    size_t parse_subscripts(const ArrayValue& a);
    void skip_conditional(const Token& at, bool stop_at_else);
    void directive_switch(const Token& t);
    void skip_switch_clauses(const Token& at);
    void directive_while(const Token& t);
    void directive_for(const Token& t);
    void directive_end(const Token& t);
    void directive_declare(const Token& t, bool local);
    void directive_macro(const Token& t);
    void directive_include(const Token& t);
    void directive_default();
    // #fopen, #fclose, #read, #write (file_io.cpp).
    void directive_fopen(const Token& t);
    void directive_fclose();
    void directive_read(const Token& t);
    void directive_write(const Token& t);
    std::string user_file_path(const std::string& name, bool write, const Token& at);
    // "(F" of #read/#write: the open file F names (and F's token in `id`).
    std::shared_ptr<UserFile> user_file_argument(const Token& directive, Token& id);
    void invoke_macro(const Token& name, const Macro& m);
    size_t find_matching_end(const Token& at);
    Binding* find_binding(uint32_t sym, int* scope_index = nullptr,
                          size_t visible_scopes = SIZE_MAX);
    void parse_top_level_item(const Token& t);
    // Where POV-Ray finds the file `name` read from file `from_file` ("" if nowhere): the
    // reading file's folder, the scene's, the library paths, the standard includes; in
    // each also `name` with ".inc" appended unless !try_inc.
    std::string resolve_include(const std::string& name, int from_file,
                                bool try_inc = true) const;
    // ---- text (shape_text.cpp)
    void parse_text(Object& out);
    // The font file POV-Ray would open for `name` ("" if none); `searched` lists the
    // folders tried.
    std::string resolve_font(const std::string& name, int from_file,
                             std::string& searched) const;
    std::shared_ptr<TrueTypeFont> load_font(const Token& at, const std::string& path,
                                            const std::string& shown);
    std::vector<uint16_t> text_codes(const Token& at, const std::string& s);
    // ---- questions about objects (object_queries.cpp)
    // min_extent / max_extent of an object identifier (`at` names it): POV-Ray's box
    // (without ParseOptions::object_queries, known for text objects only).
    Vector3 object_extent(const Token& at, const Object& o, bool max);
    // The object an identifier names, or a located error.
    std::shared_ptr<Object> object_argument(const Token& id);
    // trace(): the nearest hit from `origin` along `direction` (<0,0,0> if none) and its
    // normal (<0,0,0> if none) in `normal`.
    Vector3 trace_object(const Token& at, const std::shared_ptr<Object>& object,
                         const Point3& origin, const Vector3& direction, Vector3& normal);
    // inside(): whether `p` is inside the object (`id` names it; a patch is an error).
    bool inside_object(const Token& at, const Token& id,
                       const std::shared_ptr<Object>& object, const Point3& p);
    // Gives a closed CSG POV-Ray's box, joined from its children's (ObjectQueries).
    void close_csg_box(Object& obj);
    // global_settings { charset }: how string bytes become character codes.
    enum class Charset : uint8_t { Ascii, Utf8, Sys } charset_ = Charset::Ascii;
    // Fonts by the name written in the scene, as POV-Ray keeps them: the cmap choice and
    // the glyphs loaded stay with the first use.
    std::unordered_map<std::string, std::shared_ptr<TrueTypeFont>> fonts_;
    void finish_object(Object& obj);  // POV-Ray's post-processing of a placed object
    void place_object(Object& obj, const Object* parent,
                      std::unordered_map<uint32_t, Interior>& shared);
    uint32_t interiors_numbered_ = 0;     // Interior::id of the last interior numbered
    void add_scene_object(Object&& obj);  // to Scene::objects, unless keep_object says no
    size_t objects_populated_ = 0;        // Scene::objects' pages mapped up to this index

    const ParseOptions& options_;
    SourceManager& sources_;
    Scene scene_;
    std::vector<Frame> frames_;
    std::vector<Cond> conds_;
    std::vector<Scope> scopes_;
    std::vector<uint8_t> bound_;  // by symbol: ever bound (keywords never are)
    std::unordered_map<uint64_t, uint64_t> loop_counts_;  // #while runs, by position
    std::vector<Token> pushback_;
    Token held_token_;  // what peek_after_operand() returns for a held directive
    // --max-parse-seconds: the clock is read once per 4,096 tokens (a slow build reads
    // 4,096 tokens in a few milliseconds, so a limit of 0.02 s holds to about that);
    // resident memory, a /proc read, once per 16 clock reads.
    std::chrono::steady_clock::time_point parse_deadline_;
    uint32_t tokens_since_clock_ = 0, clock_reads_ = 0;
    void check_parse_limits(const Token& at);  // time and memory
    // ParseOptions::place: the line of the token at `offset`, and the file's name when it
    // is not the one published last.
    void publish_place(int file, uint32_t offset);
    int published_file_ = -1;
    uint64_t resident_at_start_ = 0, memory_limit_ = 0;  // bytes; limit 0: none
    std::vector<std::unique_ptr<RandomStream>> streams_;
    // POV-Ray's version state (its languageVersion and languageVersionSet): `version`
    // reads version_, 3.7 until a #version (or +MV) sets it; what must stay compatible
    // with older scenes asks effective_version(), which is 3.62 until then. Standard
    // includes save `version` and restore it with #version, so a scene without one
    // leaves colors.inc as an explicit 3.7 scene.
    int version_ = 370;
    // Inside #default { } (POV-Ray's !Not_In_Default), and whether #default gave the
    // default texture a pigment: texture_vers1.cpp's check for a pigment type.
    bool in_default_ = false;
    bool default_pigment_given_ = false;
    // An area light with media_attenuation on (the atmosphere's media are refused then).
    bool area_light_attenuated_by_media_ = false;
    // The first light with projected_through (photons are refused with it).
    std::optional<Token> projected_through_at_;
    bool version_set_ = false;
    GammaMode gamma_mode_ = GammaMode::None;  // as the parse has it so far
    bool noise_generator_given_ = false;
    void set_version(const Token& at, int version);
    void finish_version_state();  // POV-Ray's end-of-parse adjustments
    int macro_depth_ = 0;
    // Expressions, objects and patterns inside each other (parentheses, vectors, CSG,
    // pigment maps, an object in an expression through a loop that never closes it):
    // recursion on the C++ stack.
    int nesting_depth_ = 0;
    friend class NestingGuard;

  public:
    // Directives inside directives and macros inside macros recurse too (a #declare whose
    // value holds a #declare, a recursive macro with #local): past the stack this thread
    // can spare, a located error instead of a crash.
    void check_stack(const Token& at);

  private:
    uintptr_t stack_floor_ = 0;  // lowest frame address allowed; 0: unknown, no check
    bool camera_seen_ = false;
    Texture default_texture_;
    // The mesh whose own braces are being read: `hierarchy` there decides whether POV-Ray
    // builds its box tree (a later `object { M hierarchy off }` finds it built).
    const Object* mesh_in_own_braces_ = nullptr;
    std::unordered_map<const MeshData*, uint32_t> mesh_copies_;
    SharedValue<Finish> last_finish_;  // shared_finish()
    std::string scene_dir_;
    // image_map/bump_map/height_field and density_file files, for Scene::files
    std::vector<std::string> image_files_;
    std::unordered_map<std::string, std::shared_ptr<const DensityFile>> density_files_;
    std::vector<std::string> element_names_;  // rotating names bound to array elements
    size_t next_element_name_ = 0;
    friend class ExpressionParser;
    friend class FunctionCompiler;

    // Expressions inside loops and macros, compiled once per position
    // (expression_program.h). True with `out` set when a program ran in place of the
    // tokens; false when ExpressionParser must read them.
    bool try_compiled_expression(bool full, bool no_gt, Numeric& out);
    bool in_repeated_code() const;
    std::unordered_map<uint64_t, int32_t> program_by_position_;  // -1: not compiled
    struct RecentProgram {
        uint64_t key = ~uint64_t(0);  // no position has this key
        int32_t program = -1;
    } recent_programs_[64];
    std::vector<ExpressionProgram> programs_;
};

// Counts one level of nesting for its lifetime; past kMaxNesting, a located error
// instead of a stack overflow.
class NestingGuard {
  public:
    NestingGuard(Interpreter& in, const Token& at) : in_(in) {
        in_.check_stack(at);
        if (++in_.nesting_depth_ > kMaxNesting) {
            --in_.nesting_depth_;
            in_.error(at, "expressions, objects or patterns nested too deeply (limit " +
                              std::to_string(kMaxNesting) + ")");
        }
    }
    ~NestingGuard() { --in_.nesting_depth_; }
    NestingGuard(const NestingGuard&) = delete;
    NestingGuard& operator=(const NestingGuard&) = delete;

  private:
    Interpreter& in_;
};

}  // namespace povwall::parser
