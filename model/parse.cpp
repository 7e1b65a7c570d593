// parse.cpp — the scene parser: csgrt's strict subset of POV-Ray 3.7's scene
// language (docs/scene-language.md) -> the Scene AST of scene.h.
//
// Structure: a Lexer turns one file into tokens; the Parser keeps a stack of
// lexers (one per open #include) and a one-token lookahead. Directives
// (#version, #include, #declare, #local) are handled in the token stream
// itself, as POV-Ray does, so they may appear between any two tokens. The
// grammar is recursive descent; every error is a SceneError at the first
// character of the offending token.
#include "parse.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>

namespace csgrt {
namespace {

constexpr double kPi = 3.14159265358979323846;

[[noreturn]] void fail(const SourcePos& pos, const std::string& msg) { throw SceneError(pos, msg); }

std::string fmt(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

std::string line_col(const SourcePos& p) { return std::to_string(p.line) + ":" + std::to_string(p.col); }

// ---------------------------------------------------------------- keywords

// Words csgrt understands somewhere in the language.
const std::set<std::string>& csgrt_keywords() {
    static const std::set<std::string> k = {
        "sphere", "box", "cylinder", "cone", "plane", "quadric", "union", "merge", "difference",
        "intersection", "object", "camera", "light_source", "background", "global_settings",
        "location", "look_at", "angle", "right", "up", "direction", "sky", "perspective",
        "translate", "rotate", "scale", "pigment", "finish", "interior", "texture", "color",
        "colour", "rgb", "rgbf", "ambient", "diffuse", "phong", "phong_size", "reflection", "ior",
        "open", "assumed_gamma", "max_trace_level", "shadowless", "pi", "x", "y", "z"};
    return k;
}

// POV-Ray 3.7 reserved words csgrt does not support. An identifier in this
// list is reported as "unsupported keyword" rather than "undeclared
// identifier", which is what the user needs to know.
const std::set<std::string>& pov_only_keywords() {
    static const std::set<std::string> k = {
        "torus", "inverse", "normal", "photons", "disc", "mesh", "mesh2", "triangle",
        "smooth_triangle", "polygon", "prism", "lathe", "sor", "superellipsoid", "blob",
        "height_field", "julia_fractal", "isosurface", "parametric", "text", "poly", "cubic",
        "quartic", "polynomial", "bicubic_patch", "sphere_sweep", "ovus", "lemon", "light_group",
        "clipped_by", "bounded_by", "no_shadow", "no_image", "no_reflection", "double_illuminate",
        "hollow", "matrix", "transform", "rgbt", "rgbft", "red", "green", "blue", "filter",
        "transmit", "gray", "grey", "checker", "hexagon", "brick", "image_map", "bump_map",
        "material_map", "gradient", "marble", "wood", "agate", "granite", "bozo", "spotted",
        "leopard", "onion", "radial", "ripples", "waves", "wrinkles", "bumps", "dents", "crackle",
        "color_map", "colour_map", "pigment_map", "normal_map", "texture_map", "slope_map",
        "material", "media", "fog", "rainbow", "sky_sphere", "specular", "roughness", "brilliance",
        "metallic", "irid", "crand", "conserve_energy", "emission", "subsurface", "fresnel",
        "caustics", "dispersion", "dispersion_samples", "fade_distance", "fade_power", "spotlight",
        "area_light", "looks_like", "parallel", "point_at", "radius", "falloff",
        "tightness", "jitter", "adaptive", "circular", "orient", "media_interaction",
        "media_attenuation", "projected_through", "orthographic", "fisheye", "ultra_wide_angle",
        "omnimax", "panoramic", "spherical", "mesh_camera", "user_defined", "focal_point",
        "aperture", "blur_samples", "confidence", "variance", "radiosity", "ambient_light",
        "adc_bailout", "charset", "noise_generator", "number_of_waves", "sqrt", "sin", "cos",
        "tan", "asin", "acos", "atan", "atan2", "abs", "pow", "exp", "log", "ln", "min", "max",
        "mod", "floor", "ceil", "int", "div", "vlength", "vnormalize", "vcross", "vdot", "vrotate",
        "vaxis_rotate", "degrees", "radians", "clock", "clock_delta", "frame_number",
        "initial_clock", "image_width", "image_height", "true", "false", "on", "off", "yes", "no",
        "t", "u", "v", "select", "function", "pattern", "quick_color", "quick_colour", "uv_mapping",
        "warp", "turbulence", "octaves", "omega", "lambda", "frequency", "phase", "sturm",
        "split_union", "cutaway_textures", "interior_texture", "irid_wavelength", "hf_gray_16",
        "photon", "target", "refraction", "reflect", "collect", "pass_through", "spacing", "count",
        "gather", "max_intersections", "noise", "srgb", "srgbf", "srgbt", "srgbft"};
    return k;
}

bool is_object_keyword(const std::string& s) {
    static const std::set<std::string> k = {"sphere", "box", "cylinder", "cone", "plane", "quadric",
                                            "union", "merge", "difference", "intersection", "object"};
    return k.count(s) != 0;
}

bool is_csg_keyword(const std::string& s) {
    return s == "union" || s == "merge" || s == "difference" || s == "intersection";
}

const char* const kObjectList =
    "sphere, box, cylinder, cone, plane, quadric, union, merge, difference, intersection, object";
const char* const kTopLevelList =
    "sphere, box, cylinder, cone, plane, quadric, union, merge, difference, intersection, object, "
    "camera, light_source, background, global_settings";
const char* const kModifierList = "translate, rotate, scale, pigment, finish, interior, texture";

// ------------------------------------------------------------------- lexer

enum class Tok { Number, Ident, Punct, String, Directive, End };

struct Token {
    Tok kind = Tok::End;
    std::string text;  // spelling (for a String: the contents without quotes)
    double num = 0.0;
    SourcePos pos;
    bool is(char c) const { return kind == Tok::Punct && text[0] == c; }
    bool is(const char* word) const { return kind == Tok::Ident && text == word; }
};

std::string describe(const Token& t) {
    switch (t.kind) {
    case Tok::End: return "end of file";
    case Tok::String: return "\"" + t.text + "\"";
    default: return "'" + t.text + "'";
    }
}

// Splits one file into tokens, tracking 1-based line and byte column.
class Lexer {
public:
    Lexer(std::string text, std::string file, std::string base_dir)
        : s_(std::move(text)), file_(std::move(file)), base_dir_(std::move(base_dir)) {}

    const std::string& base_dir() const { return base_dir_; }
    const std::string& file() const { return file_; }

    Token next() {
        skip_blanks();
        SourcePos p = here();
        if (i_ >= s_.size()) return Token{Tok::End, "", 0.0, p};
        char c = s_[i_];
        if (std::isdigit(uc(c)) || (c == '.' && std::isdigit(uc(at(1))))) return number(p);
        if (std::isalpha(uc(c)) || c == '_') return word(p, Tok::Ident, 0);
        if (c == '"') return string(p);
        if (c == '#') return word(p, Tok::Directive, 1);
        if (c != '\0' && std::strchr("{}<>,;()+-*/=", c)) {
            advance();
            return Token{Tok::Punct, std::string(1, c), 0.0, p};
        }
        fail(p, "unexpected character " + show(c));
    }

private:
    static unsigned char uc(char c) { return static_cast<unsigned char>(c); }
    char cur() const { return at(0); }
    char at(size_t k) const { return i_ + k < s_.size() ? s_[i_ + k] : '\0'; }
    bool done() const { return i_ >= s_.size(); }
    SourcePos here() const { return SourcePos{file_, line_, col_}; }
    void advance() {
        if (s_[i_] == '\n') { ++line_; col_ = 1; } else { ++col_; }
        ++i_;
    }

    static std::string show(char c) {
        if (std::isprint(uc(c))) return std::string("'") + c + "'";
        char buf[16];
        std::snprintf(buf, sizeof buf, "0x%02x", uc(c));
        return buf;
    }

    void skip_blanks() {
        while (!done()) {
            char c = cur();
            if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v') {
                advance();
            } else if (c == '/' && at(1) == '/') {
                while (!done() && cur() != '\n') advance();
            } else if (c == '/' && at(1) == '*') {
                SourcePos open = here();
                advance(); advance();
                while (!(cur() == '*' && at(1) == '/')) {
                    if (done()) fail(open, "unterminated comment: '/*' has no closing '*/'");
                    advance();
                }
                advance(); advance();
            } else {
                break;
            }
        }
    }

    Token number(const SourcePos& p) {
        size_t start = i_;
        bool ok = true;
        while (std::isdigit(uc(cur()))) advance();
        if (cur() == '.') {
            advance();
            while (std::isdigit(uc(cur()))) advance();
        }
        if (cur() == 'e' || cur() == 'E') {
            advance();
            if (cur() == '+' || cur() == '-') advance();
            if (!std::isdigit(uc(cur()))) ok = false;
            while (std::isdigit(uc(cur()))) advance();
        }
        // A number glued to letters or another '.' (1.2.3, 1e, 3x) is one
        // malformed number, not two tokens: that is almost always a typo.
        while (std::isalnum(uc(cur())) || cur() == '_' || cur() == '.') { ok = false; advance(); }
        std::string text = s_.substr(start, i_ - start);
        if (!ok) fail(p, "malformed number '" + text + "'");
        return Token{Tok::Number, text, std::strtod(text.c_str(), nullptr), p};
    }

    // An identifier, or (skip = 1) a directive '#name'.
    Token word(const SourcePos& p, Tok kind, int skip) {
        size_t start = i_;
        for (int k = 0; k < skip; ++k) advance();
        while (std::isalnum(uc(cur())) || cur() == '_') advance();
        std::string text = s_.substr(start, i_ - start);
        if (kind == Tok::Directive && text.size() == 1) fail(p, "expected a directive name after '#'");
        return Token{kind, text, 0.0, p};
    }

    Token string(const SourcePos& p) {
        advance();
        size_t start = i_;
        while (cur() != '"') {
            if (done() || cur() == '\n') fail(p, "unterminated string");
            advance();
        }
        std::string text = s_.substr(start, i_ - start);
        advance();
        return Token{Tok::String, text, 0.0, p};
    }

    std::string s_, file_, base_dir_;
    size_t i_ = 0;
    int line_ = 1, col_ = 1;
};

// ------------------------------------------------------------ file helpers

std::string dirname_of(const std::string& path) {
    size_t k = path.find_last_of('/');
    if (k == std::string::npos) return "";
    return k == 0 ? "/" : path.substr(0, k);
}

std::string join_path(const std::string& dir, const std::string& name) {
    if (dir.empty() || (!name.empty() && name[0] == '/')) return name;
    return dir.back() == '/' ? dir + name : dir + "/" + name;
}

bool read_file(const std::string& path, std::string& out) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    std::ostringstream ss;
    ss << in.rdbuf();
    out = ss.str();
    return true;
}

// ------------------------------------------------------------- transforms

glm::dmat4 translation(const glm::dvec3& v) {
    glm::dmat4 m(1.0);
    m[3] = glm::dvec4(v, 1.0);
    return m;
}

glm::dmat4 scaling(const glm::dvec3& v) {
    glm::dmat4 m(1.0);
    m[0][0] = v.x; m[1][1] = v.y; m[2][2] = v.z;
    return m;
}

// Right-hand rotations about x, then y, then z (glm is column-major: m[col][row]).
glm::dmat4 rotation(const glm::dvec3& degrees) {
    glm::dvec3 a = degrees * (kPi / 180.0);
    glm::dmat4 rx(1.0), ry(1.0), rz(1.0);
    rx[1][1] = std::cos(a.x); rx[2][1] = -std::sin(a.x);
    rx[1][2] = std::sin(a.x); rx[2][2] = std::cos(a.x);
    ry[0][0] = std::cos(a.y); ry[2][0] = std::sin(a.y);
    ry[0][2] = -std::sin(a.y); ry[2][2] = std::cos(a.y);
    rz[0][0] = std::cos(a.z); rz[1][0] = -std::sin(a.z);
    rz[0][1] = std::sin(a.z); rz[1][1] = std::cos(a.z);
    return rz * ry * rx;
}

// ------------------------------------------------------------------ values

// A float (n = 1) or a vector of 2..5 components, with where it started.
struct Value {
    int n = 1;
    std::array<double, 5> c{};
    SourcePos pos;
};

Value make_float(double f, const SourcePos& p) {
    Value v;
    v.c[0] = f;
    v.pos = p;
    return v;
}

Value make_vec3(const glm::dvec3& d, const SourcePos& p) {
    Value v;
    v.n = 3;
    v.c = {d.x, d.y, d.z, 0.0, 0.0};
    v.pos = p;
    return v;
}

// POV-Ray promotes a float to a vector with every component equal to it.
Value promote(const Value& v, int n) {
    if (v.n != 1) return v;
    Value r = v;
    r.n = n;
    for (int i = 0; i < n; ++i) r.c[i] = v.c[0];
    return r;
}

std::string shape_of(const Value& v) {
    return v.n == 1 ? "a float" : "a " + std::to_string(v.n) + "-component vector";
}

// What a #declare name stands for.
struct Declared {
    bool is_object = false;
    Value value;
    Object object;
};

// camera items as written; POV-Ray 3.5+ applies them in a fixed order after
// the block is read (angle, then look_at), whatever order they were written in.
struct CameraItems {
    std::optional<glm::dvec3> location, look_at, right, up, direction, sky;
    std::optional<double> angle;
    SourcePos look_at_pos;
};

// ------------------------------------------------------------------ parser

class Parser {
public:
    explicit Parser(Scene& scene) : scene_(scene) {}

    void push_file(std::string text, const std::string& file, const std::string& base_dir) {
        lexers_.push_back(std::make_unique<Lexer>(std::move(text), file, base_dir));
    }

    // scene := statement* EOF
    void parse_scene() {
        for (;;) {
            Token t = peek();
            if (t.kind == Tok::End) return;
            next();
            if (t.kind == Tok::Ident && is_object_keyword(t.text)) {
                scene_.objects.push_back(parse_object(t));
            } else if (t.is("camera")) {
                parse_camera(t);
            } else if (t.is("light_source")) {
                parse_light(t);
            } else if (t.is("background")) {
                parse_background(t);
            } else if (t.is("global_settings")) {
                parse_global_settings(t);
            } else if (is_declared_object(t)) {
                scene_.objects.push_back(decls_[t.text].object);  // POV-Ray allows a bare name here
            } else {
                unexpected(t, std::string("a scene item (") + kTopLevelList + ") or a directive",
                           kTopLevelList);
            }
        }
    }

private:
    // ---------------------------------------------------------- token stream

    const Token& peek() {
        if (!has_la_) {
            Token t = fetch();
            la_ = t;
            has_la_ = true;
        }
        return la_;
    }

    Token next() {
        peek();
        has_la_ = false;
        return la_;
    }

    // The next token of the current file, falling back to the including file
    // at the end of an included one.
    Token raw() {
        for (;;) {
            Token t = lexers_.back()->next();
            if (t.kind == Tok::End && lexers_.size() > 1) {
                lexers_.pop_back();
                continue;
            }
            return t;
        }
    }

    // The next token after processing any directives. While a #declare or
    // #version value is being read, directives are returned as tokens, so a
    // missing ';' is reported as such instead of running the next directive.
    Token fetch() {
        for (;;) {
            Token t = raw();
            if (t.kind != Tok::Directive || in_directive_ > 0) return t;
            directive(t);
            if (has_la_) {  // the directive peeked past its own end
                has_la_ = false;
                return la_;
            }
        }
    }

    bool at_punct(char c) { return peek().is(c); }

    void optional_comma() {
        if (at_punct(',')) next();
    }

    void expect_punct(char c, const std::string& what) {
        Token t = peek();
        if (!t.is(c)) unexpected(t, std::string("'") + c + "' " + what);
        next();
    }

    bool is_declared_object(const Token& t) const {
        auto it = decls_.find(t.text);
        return t.kind == Tok::Ident && it != decls_.end() && it->second.is_object;
    }

    // The error for a token that does not fit: end of file, an unsupported
    // POV-Ray keyword, an undeclared name, or simply the wrong token.
    [[noreturn]] void unexpected(const Token& t, const std::string& expected,
                                 const std::string& supported = "") {
        if (t.kind == Tok::End) fail(t.pos, "unexpected end of file: expected " + expected);
        if (t.kind == Tok::Ident && !csgrt_keywords().count(t.text) && !decls_.count(t.text)) {
            if (pov_only_keywords().count(t.text))
                fail(t.pos, "unsupported keyword '" + t.text + "' (csgrt supports here: " +
                                (supported.empty() ? expected : supported) + ")");
            fail(t.pos, "undeclared identifier '" + t.text + "'");
        }
        if (t.kind == Tok::Directive)
            fail(t.pos, "expected " + expected + ", found directive '" + t.text + "'");
        fail(t.pos, "expected " + expected + ", found " + describe(t));
    }

    // The error inside a '{...}' block opened by `kw`.
    [[noreturn]] void unexpected_in_block(const Token& t, const Token& kw, const std::string& items) {
        unexpected(t, "'}' to close '" + kw.text + "' opened at " + line_col(kw.pos), items);
    }

    void expect_open(const Token& kw) { expect_punct('{', "after '" + kw.text + "'"); }

    // ------------------------------------------------------------ directives

    void directive(const Token& d) {
        if (d.text == "#version") {
            ++in_directive_;
            parse_float("#version");
            expect_punct(';', "after '#version' number");
            --in_directive_;
        } else if (d.text == "#include") {
            include(d);
        } else if (d.text == "#declare" || d.text == "#local") {
            declare(d);
        } else {
            fail(d.pos, "unsupported directive '" + d.text +
                            "' (csgrt supports #version, #include, #declare, #local)");
        }
    }

    void include(const Token& d) {
        Token name = raw();
        if (name.kind != Tok::String) unexpected(name, "a quoted file name after '#include'");
        std::string path = join_path(lexers_.back()->base_dir(), name.text);
        if (lexers_.size() >= 32) fail(d.pos, "#include nested too deeply (recursive include of '" + name.text + "'?)");
        std::string text;
        if (!read_file(path, text)) fail(d.pos, "cannot open include file '" + name.text + "' (looked for '" + path + "')");
        push_file(std::move(text), path, dirname_of(path));
    }

    // #declare NAME = float | vector | object ;   (';' optional after an object)
    void declare(const Token& d) {
        ++in_directive_;
        Token name = next();
        if (name.kind != Tok::Ident) unexpected(name, "an identifier after '" + d.text + "'");
        if (csgrt_keywords().count(name.text) || pov_only_keywords().count(name.text))
            fail(name.pos, "cannot " + d.text + " '" + name.text + "': it is a keyword");
        expect_punct('=', "after '" + d.text + " " + name.text + "'");
        Declared decl;
        const Token& t = peek();
        if (t.kind == Tok::Ident && is_object_keyword(t.text)) {
            decl.is_object = true;
            decl.object = parse_object(next());
            decls_[name.text] = decl;  // stored before peeking for ';', which may run the next directive
            --in_directive_;
            if (at_punct(';')) next();
            return;
        }
        decl.value = parse_expr("the value of '" + name.text + "'");
        expect_punct(';', "after the value of '" + d.text + " " + name.text + "'");
        decls_[name.text] = decl;
        --in_directive_;
    }

    // ----------------------------------------------------------- expressions

    // expr := term (('+' | '-') term)*
    Value parse_expr(const std::string& what) {
        Value a = parse_term(what);
        while (at_punct('+') || at_punct('-')) {
            Token op = next();
            a = combine(a, parse_term(what), op);
        }
        return a;
    }

    // term := unary (('*' | '/') unary)*
    Value parse_term(const std::string& what) {
        Value a = parse_unary(what);
        while (at_punct('*') || at_punct('/')) {
            Token op = next();
            a = combine(a, parse_unary(what), op);
        }
        return a;
    }

    // unary := ('-' | '+') unary | primary
    Value parse_unary(const std::string& what) {
        if (at_punct('-') || at_punct('+')) {
            Token op = next();
            Value v = parse_unary(what);
            if (op.is('-'))
                for (int i = 0; i < v.n; ++i) v.c[i] = -v.c[i];
            v.pos = op.pos;
            return v;
        }
        return parse_primary(what);
    }

    // primary := number | '(' expr ')' | '<' expr (',' expr)* '>' | pi | x | y | z | NAME
    Value parse_primary(const std::string& what) {
        Token t = peek();
        if (t.kind == Tok::Number) return next(), make_float(t.num, t.pos);
        if (t.is('(')) {
            next();
            Value v = parse_expr(what);
            expect_punct(')', "to close '(' at " + line_col(t.pos));
            v.pos = t.pos;
            return v;
        }
        if (t.is('<')) return parse_vector_literal(what);
        if (t.kind == Tok::Ident) {
            if (t.text == "pi") return next(), make_float(kPi, t.pos);
            if (t.text == "x") return next(), make_vec3({1, 0, 0}, t.pos);
            if (t.text == "y") return next(), make_vec3({0, 1, 0}, t.pos);
            if (t.text == "z") return next(), make_vec3({0, 0, 1}, t.pos);
            auto it = decls_.find(t.text);
            if (it != decls_.end()) {
                if (it->second.is_object)
                    fail(t.pos, "'" + t.text + "' is an object, not a float or vector (needed for " + what + ")");
                next();
                Value v = it->second.value;
                v.pos = t.pos;
                return v;
            }
        }
        unexpected(t, "a float or vector for " + what);
    }

    Value parse_vector_literal(const std::string& what) {
        Token open = next();
        Value v;
        v.pos = open.pos;
        v.n = 0;
        for (;;) {
            Value comp = parse_expr(what);
            if (comp.n != 1) fail(comp.pos, "a vector component must be a float, found " + shape_of(comp));
            if (v.n == 5) fail(comp.pos, "too many vector components (at most 5)");
            v.c[v.n++] = comp.c[0];
            Token t = peek();
            if (t.is('>')) break;
            if (!t.is(',')) unexpected(t, "',' or '>' in the vector opened at " + line_col(open.pos));
            next();
        }
        next();
        if (v.n < 2) fail(open.pos, "a vector needs at least 2 components");
        return v;
    }

    Value combine(Value a, Value b, const Token& op) {
        if (a.n != b.n) {
            if (a.n == 1) a = promote(a, b.n);
            else if (b.n == 1) b = promote(b, a.n);
            else fail(op.pos, "cannot combine " + shape_of(a) + " and " + shape_of(b) + " with '" + op.text + "'");
        }
        for (int i = 0; i < a.n; ++i) {
            switch (op.text[0]) {
            case '+': a.c[i] += b.c[i]; break;
            case '-': a.c[i] -= b.c[i]; break;
            case '*': a.c[i] *= b.c[i]; break;
            default:
                if (b.c[i] == 0.0) fail(op.pos, "division by zero");
                a.c[i] /= b.c[i];
            }
        }
        return a;
    }

    double parse_float(const std::string& what, SourcePos* at = nullptr) {
        Value v = parse_expr(what);
        if (v.n != 1) fail(v.pos, "expected a float for " + what + ", found " + shape_of(v));
        if (at) *at = v.pos;
        return v.c[0];
    }

    glm::dvec3 parse_vec3(const std::string& what, SourcePos* at = nullptr) {
        Value v = promote(parse_expr(what), 3);
        if (v.n != 3) fail(v.pos, "expected a 3-component vector for " + what + ", found " + shape_of(v));
        if (at) *at = v.pos;
        return {v.c[0], v.c[1], v.c[2]};
    }

    double parse_nonnegative(const std::string& what) {
        SourcePos at;
        double f = parse_float(what, &at);
        if (f < 0.0) fail(at, what + " must not be negative, got " + fmt(f));
        return f;
    }

    // --------------------------------------------------------------- colours

    static bool starts_color(const Token& t) {
        return t.is("color") || t.is("colour") || t.is("rgb") || t.is("rgbf");
    }

    // colour := [color | colour] (rgb V | rgbf V | V). Returns 3 components,
    // or 4 (rgbf) when allow_filter.
    Value parse_color(const std::string& what, bool allow_filter) {
        Token t = peek();
        if (t.is("color") || t.is("colour")) {
            next();
            t = peek();
        }
        int n = 0;
        if (t.is("rgb")) { next(); n = 3; }
        else if (t.is("rgbf")) {
            if (!allow_filter) fail(t.pos, "'rgbf' is not allowed in " + what + " (use rgb)");
            next();
            n = 4;
        }
        Value v = parse_expr(what);
        if (n != 0) v = promote(v, n);
        else v = promote(v, 3);  // `color V`: the vector's size says rgb or rgbf
        if (v.n == 5) fail(v.pos, "a 5-component colour has a transmit value; csgrt supports rgb and rgbf only");
        if (v.n == 4 && !allow_filter) fail(v.pos, "expected an rgb colour for " + what + ", found a 4-component vector");
        if ((n != 0 && v.n != n) || v.n < 3)
            fail(v.pos, "expected a " + std::to_string(n ? n : 3) + "-component colour for " + what + ", found " + shape_of(v));
        return v;
    }

    // --------------------------------------------------------------- objects

    Object parse_object(const Token& kw) {
        Object o;
        o.pos = kw.pos;
        o.keyword = kw.text;
        expect_open(kw);
        if (kw.text == "object") o = parse_instance(kw);
        else if (is_csg_keyword(kw.text)) parse_csg_children(o, kw);
        else parse_primitive(o, kw);
        parse_modifiers(o, kw);
        return o;
    }

    // object { NAME mods } or object { OBJECT mods }: a deep copy that the
    // following modifiers then transform and re-material.
    Object parse_instance(const Token& kw) {
        Token t = peek();
        if (is_declared_object(t)) {
            next();
            return decls_[t.text].object;
        }
        if (t.kind == Tok::Ident && is_object_keyword(t.text)) return parse_object(next());
        if (t.kind == Tok::Ident && decls_.count(t.text))
            fail(t.pos, "'" + t.text + "' is a float or vector, not an object");
        unexpected(t, "a declared object name or an object after '" + kw.text + " {'", kObjectList);
    }

    void parse_csg_children(Object& o, const Token& kw) {
        o.is_csg = true;
        o.op = kw.text == "union" ? CsgOp::Union
             : kw.text == "merge" ? CsgOp::Merge
             : kw.text == "difference" ? CsgOp::Difference : CsgOp::Intersection;
        for (;;) {
            Token t = peek();
            if (t.kind == Tok::Ident && is_object_keyword(t.text)) {
                o.children.push_back(parse_object(next()));
            } else if (is_declared_object(t)) {
                fail(t.pos, "use 'object { " + t.text + " }' to place declared object '" + t.text +
                                "' inside '" + kw.text + "'");
            } else {
                break;
            }
        }
        size_t need = o.op == CsgOp::Difference ? 2 : 1;
        if (o.children.size() >= need) return;
        // Too few objects: report a token that is neither '}' nor a modifier
        // (e.g. 'torus') for what it is; otherwise the group is too small.
        Token t = peek();
        static const std::set<std::string> modifiers = {"translate", "rotate", "scale", "pigment",
                                                        "finish", "interior", "texture"};
        bool modifier = t.kind == Tok::Ident && modifiers.count(t.text);
        if (!t.is('}') && !modifier)
            unexpected(t, std::string("an object (") + kObjectList + ") in '" + kw.text + "'", kObjectList);
        if (o.children.size() < need)
            fail(kw.pos, "'" + kw.text + "' needs at least " + std::to_string(need) + " object" +
                             (need > 1 ? "s" : "") + ", found " + std::to_string(o.children.size()));
    }

    void parse_primitive(Object& o, const Token& kw) {
        const std::string& k = kw.text;
        if (k == "sphere") parse_sphere(o);
        else if (k == "box") parse_box(o);
        else if (k == "cylinder") parse_cylinder(o);
        else if (k == "cone") parse_cone(o);
        else if (k == "plane") parse_plane(o);
        else parse_quadric(o);
    }

    // sphere { <centre>, radius }
    void parse_sphere(Object& o) {
        o.prim = PrimKind::Sphere;
        o.v0 = parse_vec3("sphere centre");
        optional_comma();
        SourcePos at;
        o.r0 = parse_float("sphere radius", &at);
        if (o.r0 <= 0.0) fail(at, "sphere radius must be positive, got " + fmt(o.r0));
    }

    // box { <corner1>, <corner2> }
    void parse_box(Object& o) {
        o.prim = PrimKind::Box;
        o.v0 = parse_vec3("box corner 1");
        optional_comma();
        o.v1 = parse_vec3("box corner 2");
    }

    // cylinder { <base>, <cap>, radius [open] }   (open is read with the modifiers)
    void parse_cylinder(Object& o) {
        o.prim = PrimKind::Cylinder;
        SourcePos base_at;
        o.v0 = parse_vec3("cylinder base", &base_at);
        optional_comma();
        o.v1 = parse_vec3("cylinder cap");
        optional_comma();
        SourcePos at;
        o.r0 = parse_float("cylinder radius", &at);
        if (o.r0 < 0.0) fail(at, "negative cylinder radius " + fmt(o.r0));
        if (o.r0 == 0.0) fail(at, "cylinder radius must be positive, got 0");
        if (o.v0 == o.v1) fail(base_at, "cylinder base and cap are the same point (zero-length axis)");
    }

    // cone { <base>, base_radius, <cap>, cap_radius [open] }
    void parse_cone(Object& o) {
        o.prim = PrimKind::Cone;
        SourcePos base_at, r0_at, r1_at;
        o.v0 = parse_vec3("cone base", &base_at);
        optional_comma();
        o.r0 = parse_float("cone base radius", &r0_at);
        optional_comma();
        o.v1 = parse_vec3("cone cap");
        optional_comma();
        o.r1 = parse_float("cone cap radius", &r1_at);
        if (o.r0 < 0.0) fail(r0_at, "negative cone base radius " + fmt(o.r0));
        if (o.r1 < 0.0) fail(r1_at, "negative cone cap radius " + fmt(o.r1));
        if (o.r0 == 0.0 && o.r1 == 0.0) fail(r0_at, "cone radii are both zero");
        if (o.v0 == o.v1) fail(base_at, "cone base and cap are the same point (zero-length axis)");
    }

    // plane { <normal>, distance }
    void parse_plane(Object& o) {
        o.prim = PrimKind::Plane;
        SourcePos at;
        o.v0 = parse_vec3("plane normal", &at);
        if (o.v0 == glm::dvec3(0.0)) fail(at, "plane normal must not be zero");
        optional_comma();
        o.r0 = parse_float("plane distance");
    }

    // quadric { <A,B,C>, <D,E,F>, <G,H,I>, J }
    void parse_quadric(Object& o) {
        o.prim = PrimKind::Quadric;
        const char* names[3] = {"quadric <A,B,C>", "quadric <D,E,F>", "quadric <G,H,I>"};
        for (int i = 0; i < 3; ++i) {
            glm::dvec3 v = parse_vec3(names[i]);
            o.coef[3 * i] = v.x; o.coef[3 * i + 1] = v.y; o.coef[3 * i + 2] = v.z;
            optional_comma();
        }
        o.coef[9] = parse_float("quadric J");
    }

    // --------------------------------------------------------------- modifiers

    // (translate V | rotate V | scale V | pigment{} | finish{} | interior{}
    //  | texture{} | open)* '}'
    void parse_modifiers(Object& o, const Token& kw) {
        bool can_open = kw.text == "cylinder" || kw.text == "cone";
        for (;;) {
            Token t = peek();
            if (t.is('}')) { next(); return; }
            if (t.is("translate")) { next(); o.transform = translation(parse_vec3("translate")) * o.transform; }
            else if (t.is("rotate")) { next(); o.transform = rotation(parse_vec3("rotate")) * o.transform; }
            else if (t.is("scale")) { next(); o.transform = scaling(parse_scale()) * o.transform; }
            else if (t.is("pigment")) { next(); o.pigment = parse_pigment(t, o.pigment.value_or(Pigment{})); }
            else if (t.is("finish")) { next(); o.finish = parse_finish(t, o.finish.value_or(Finish{})); }
            else if (t.is("interior")) { next(); o.interior = parse_interior(t, o.interior.value_or(Interior{})); }
            else if (t.is("texture")) { next(); parse_texture(t, o); }
            else if (t.is("open") && can_open) { next(); o.open = true; }
            else if (o.is_csg && kw.text != "object" && t.kind == Tok::Ident && is_object_keyword(t.text))
                fail(t.pos, "'" + t.text + "' must come before the modifiers of '" + kw.text + "' opened at " +
                                line_col(kw.pos) + " (POV-Ray reads a group's objects first)");
            else unexpected_in_block(t, kw, std::string(o.is_csg && kw.text != "object" ? kObjectList + std::string(", ") : "") +
                                                kModifierList + (can_open ? ", open" : ""));
        }
    }

    glm::dvec3 parse_scale() {
        SourcePos at;
        glm::dvec3 s = parse_vec3("scale", &at);
        if (s.x == 0.0 || s.y == 0.0 || s.z == 0.0)
            fail(at, "scale component is zero (<" + fmt(s.x) + ", " + fmt(s.y) + ", " + fmt(s.z) + ">)");
        return s;
    }

    // pigment { colour } — starts from the object's current pigment, as
    // POV-Ray's pigment modifier does.
    Pigment parse_pigment(const Token& kw, Pigment p) {
        expect_open(kw);
        for (;;) {
            Token t = peek();
            if (t.is('}')) { next(); return p; }
            if (!starts_color(t)) unexpected_in_block(t, kw, "color rgb <r,g,b>, color rgbf <r,g,b,f>");
            Value c = parse_color("pigment colour", true);
            p.rgb = {c.c[0], c.c[1], c.c[2]};
            p.filter = c.n == 4 ? c.c[3] : 0.0;
        }
    }

    // finish { ambient F diffuse F phong F phong_size F reflection F } —
    // starts from the object's current finish, as POV-Ray does.
    Finish parse_finish(const Token& kw, Finish f) {
        expect_open(kw);
        for (;;) {
            Token t = peek();
            if (t.is('}')) { next(); return f; }
            next();
            if (t.is("ambient")) f.ambient = parse_nonnegative("finish ambient");
            else if (t.is("diffuse")) f.diffuse = parse_nonnegative("finish diffuse");
            else if (t.is("phong")) f.phong = parse_nonnegative("finish phong");
            else if (t.is("reflection")) {
                if (at_punct('{')) fail(peek().pos, "the 'reflection { ... }' block is not supported; write 'reflection F'");
                f.reflection = parse_nonnegative("finish reflection");
            } else if (t.is("phong_size")) {
                SourcePos at;
                f.phong_size = parse_float("finish phong_size", &at);
                if (f.phong_size <= 0.0) fail(at, "finish phong_size must be positive, got " + fmt(f.phong_size));
            } else {
                unexpected_in_block(t, kw, "ambient, diffuse, phong, phong_size, reflection");
            }
        }
    }

    // interior { ior F }
    Interior parse_interior(const Token& kw, Interior in) {
        expect_open(kw);
        for (;;) {
            Token t = peek();
            if (t.is('}')) { next(); return in; }
            if (!t.is("ior")) unexpected_in_block(t, kw, "ior");
            next();
            SourcePos at;
            in.ior = parse_float("interior ior", &at);
            if (in.ior <= 0.0) fail(at, "interior ior must be positive, got " + fmt(in.ior));
        }
    }

    // texture { pigment{} finish{} } — a new texture from POV-Ray's defaults,
    // so it sets both the pigment and the finish.
    void parse_texture(const Token& kw, Object& o) {
        expect_open(kw);
        Pigment p;
        Finish f;
        for (;;) {
            Token t = peek();
            if (t.is('}')) { next(); break; }
            if (t.is("pigment")) { next(); p = parse_pigment(t, p); }
            else if (t.is("finish")) { next(); f = parse_finish(t, f); }
            else unexpected_in_block(t, kw, "pigment, finish");
        }
        o.pigment = p;
        o.finish = f;
    }

    // ----------------------------------------------------- scene-level items

    void parse_camera(const Token& kw) {
        if (scene_.has_camera)
            fail(kw.pos, "duplicate camera (the first is at " + scene_.camera.pos.str() + "); csgrt allows one camera");
        expect_open(kw);
        CameraItems it;
        for (;;) {
            Token t = peek();
            if (t.is('}')) { next(); break; }
            next();
            if (t.is("location")) it.location = parse_vec3("camera location");
            else if (t.is("look_at")) it.look_at = parse_vec3("camera look_at", &it.look_at_pos);
            else if (t.is("right")) it.right = nonzero_vec3("camera right");
            else if (t.is("up")) it.up = nonzero_vec3("camera up");
            else if (t.is("direction")) it.direction = nonzero_vec3("camera direction");
            else if (t.is("sky")) it.sky = nonzero_vec3("camera sky");
            else if (t.is("angle")) it.angle = parse_angle();
            else if (t.is("perspective")) continue;
            else unexpected_in_block(t, kw, "location, look_at, angle, right, up, direction, sky, perspective");
        }
        scene_.camera = resolve_camera(it, kw.pos);
        scene_.has_camera = true;
    }

    glm::dvec3 nonzero_vec3(const std::string& what) {
        SourcePos at;
        glm::dvec3 v = parse_vec3(what, &at);
        if (v == glm::dvec3(0.0)) fail(at, what + " must not be zero");
        return v;
    }

    double parse_angle() {
        SourcePos at;
        double a = parse_float("camera angle", &at);
        if (a <= 0.0 || a >= 180.0) fail(at, "camera angle must be between 0 and 180 degrees (exclusive), got " + fmt(a));
        return a;
    }

    // POV-Ray 3.7's resolution (parser, language version >= 3.5): take the
    // last value of each item, then apply angle, then look_at.
    static Camera resolve_camera(const CameraItems& it, const SourcePos& pos) {
        Camera c;
        c.pos = pos;
        glm::dvec3 sky = it.sky.value_or(glm::dvec3(0, 1, 0));
        if (it.location) c.location = *it.location;
        if (it.direction) c.direction = *it.direction;
        if (it.right) c.right = *it.right;
        if (it.up) c.up = *it.up;
        if (it.angle)
            c.direction = glm::normalize(c.direction) * (0.5 * glm::length(c.right) / std::tan(*it.angle * kPi / 360.0));
        if (it.look_at) apply_look_at(c, *it.look_at, sky, it.look_at_pos);
        return c;
    }

    static void apply_look_at(Camera& c, const glm::dvec3& look_at, const glm::dvec3& sky, const SourcePos& at) {
        double dl = glm::length(c.direction), ul = glm::length(c.up), rl = glm::length(c.right);
        double handedness = glm::dot(glm::cross(c.up, c.direction), c.right);
        glm::dvec3 d = look_at - c.location;
        if (glm::dot(d, d) < 1e-10) fail(at, "camera location and look_at must be different points");
        d = glm::normalize(d);
        glm::dvec3 r = glm::cross(sky, d);
        // Looking along the sky vector: POV-Ray keeps the given right vector.
        if (std::fabs(r.x) < 1e-10 && std::fabs(r.y) < 1e-10 && std::fabs(r.z) < 1e-10) r = c.right;
        r = glm::normalize(r);
        c.up = glm::cross(d, r) * ul;
        c.direction = d * dl;
        c.right = r * (handedness > 0.0 ? rl : -rl);
    }

    // light_source { <location> [colour] [shadowless] }
    void parse_light(const Token& kw) {
        expect_open(kw);
        Light l;
        l.pos = kw.pos;
        l.location = parse_vec3("light_source location");
        optional_comma();
        for (;;) {
            Token t = peek();
            if (t.is('}')) { next(); break; }
            if (t.is("shadowless")) {   // lights every point it faces: no shadow ray (docs/effects.md)
                next();
                l.shadowless = true;
                continue;
            }
            if (!starts_color(t)) unexpected_in_block(t, kw, "color rgb <r,g,b>, shadowless");
            Value c = parse_color("light_source colour", false);
            l.color = {c.c[0], c.c[1], c.c[2]};
        }
        scene_.lights.push_back(l);
    }

    // background { colour }
    void parse_background(const Token& kw) {
        expect_open(kw);
        for (;;) {
            Token t = peek();
            if (t.is('}')) { next(); return; }
            if (!starts_color(t)) unexpected_in_block(t, kw, "color rgb <r,g,b>");
            Value c = parse_color("background colour", false);
            scene_.background = {c.c[0], c.c[1], c.c[2]};
        }
    }

    // global_settings { assumed_gamma 1.0 max_trace_level N }
    void parse_global_settings(const Token& kw) {
        expect_open(kw);
        for (;;) {
            Token t = peek();
            if (t.is('}')) { next(); return; }
            next();
            SourcePos at;
            if (t.is("assumed_gamma")) {
                double g = parse_float("assumed_gamma", &at);
                if (std::fabs(g - 1.0) > 1e-9)
                    fail(at, "assumed_gamma must be 1.0 (csgrt computes in linear light), got " + fmt(g));
            } else if (t.is("max_trace_level")) {
                double n = parse_float("max_trace_level", &at);
                if (n < 1.0 || n != std::floor(n) || n > 1e6)
                    fail(at, "max_trace_level must be a positive integer, got " + fmt(n));
                scene_.max_trace_level = static_cast<int>(n);
                scene_.has_max_trace_level = true;
            } else {
                unexpected_in_block(t, kw, "assumed_gamma, max_trace_level");
            }
        }
    }

    Scene& scene_;
    std::vector<std::unique_ptr<Lexer>> lexers_;
    Token la_;
    bool has_la_ = false;
    int in_directive_ = 0;
    std::map<std::string, Declared> decls_;
};

Scene parse(std::string text, const std::string& file, const std::string& base_dir) {
    Scene scene;
    scene.file = file;
    Parser p(scene);
    p.push_file(std::move(text), file, base_dir);
    p.parse_scene();
    return scene;
}

}  // namespace

Scene parse_scene_file(const std::string& path) {
    std::string text;
    if (!read_file(path, text)) throw SceneError(SourcePos{path, 1, 1}, "cannot open scene file '" + path + "'");
    return parse(std::move(text), path, dirname_of(path));
}

Scene parse_scene_string(const std::string& text, const std::string& filename) {
    return parse(text, filename, "");
}

}  // namespace csgrt
