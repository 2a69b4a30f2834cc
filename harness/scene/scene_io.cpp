#include "scene_io.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <sstream>

#include <unistd.h>

#include "io.h"
#include "rng.h"
#include "names.h"

namespace bvb {

namespace fs = std::filesystem;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kMaxFrames = 100000;
// Paths, sides and positions: every arena is a room of a few hundred inches at most.
constexpr double kMaxPathIn = 1000;
constexpr double kMaxTurnDeg = 3600;  // ten full turns
// fx as a multiple of the width: fields of view from 2 atan(10) = 169 deg to 2 atan(1/40) = 2.9 deg.
constexpr double kMinFxPerWidth = 0.05, kMaxFxPerWidth = 20;
constexpr long long kMaxSceneSeed = 999999999999999999ll;  // 18 digits, any 64-bit reader takes it

std::string num(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.10g", v);
  return b;
}

[[noreturn]] void spec_error(const std::string &key, const std::string &msg) {
  throw InputError("scene spec: " + key + ": " + msg);
}

double parse_num(const std::string &key, const std::string &v, double lo, double hi) {
  errno = 0;
  char *end = nullptr;
  const double d = std::strtod(v.c_str(), &end);
  if (v.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(d) ||
      v.find_first_of("xXpP") != std::string::npos)
    spec_error(key, "not a number: '" + v + "'");
  if (d < lo || d > hi) spec_error(key, v + " is out of range " + num(lo) + ".." + num(hi));
  return d;
}

long long parse_int(const std::string &key, const std::string &v, long long lo, long long hi) {
  if (v.empty() || v.find_first_not_of("0123456789") != std::string::npos)
    spec_error(key, "not a whole number: '" + v + "'");
  // More than 18 digits is beyond every key's range (and might not fit 64 bits).
  if (v.size() > 18) spec_error(key, v + " is out of range " + std::to_string(lo) + ".." + std::to_string(hi));
  const long long n = std::stoll(v);
  if (n < lo || n > hi)
    spec_error(key, v + " is out of range " + std::to_string(lo) + ".." + std::to_string(hi));
  return n;
}

bool parse_bool(const std::string &key, const std::string &v) {
  if (v == "1") return true;
  if (v == "0") return false;
  spec_error(key, "expected 0 or 1, not '" + v + "'");
}

struct KeyDef {
  const char *name;
  std::string range;  // what the key accepts, for --help and the documentation
  std::function<void(SceneSpec &, const std::string &)> set;
  std::function<std::string(const SceneSpec &)> get;
};

// A real-valued key between lo and hi (in `unit`), stored in a SceneSpec member.
KeyDef real_key(const char *name, double SceneSpec::*field, double lo, double hi, const char *unit) {
  return {name, num(lo) + ".." + num(hi) + (*unit ? " " : "") + unit,
          [=](SceneSpec &s, const std::string &v) { s.*field = parse_num(name, v, lo, hi); },
          [=](const SceneSpec &s) { return num(s.*field); }};
}

// A whole-number key between lo and hi, stored in an int member.
KeyDef int_key(const char *name, int SceneSpec::*field, int lo, int hi, const char *unit) {
  return {name, std::to_string(lo) + ".." + std::to_string(hi) + (*unit ? " " : "") + unit,
          [=](SceneSpec &s, const std::string &v) { s.*field = int(parse_int(name, v, lo, hi)); },
          [=](const SceneSpec &s) { return std::to_string(s.*field); }};
}

KeyDef bool_key(const char *name, bool SceneSpec::*field) {
  return {name, "0 or 1", [=](SceneSpec &s, const std::string &v) { s.*field = parse_bool(name, v); },
          [=](const SceneSpec &s) { return std::string(s.*field ? "1" : "0"); }};
}

// The ranges say what a scene can mean: a path within any room an arena describes, a camera
// on a robot of the SRV-1's size, encoders a wheel could have. A value outside is a mistake
// (a sign or a unit), refused before anything is rendered.
const std::vector<KeyDef> &spec_keys() {
  static const std::vector<KeyDef> keys = {
      {"arena", "a name in frames/arenas/ or an arena file",
       [](SceneSpec &s, const std::string &v) {
         if (v.empty() || v.find_first_of(",= ") != std::string::npos)
           spec_error("arena", "expected an arena name or file, not '" + v + "'");
         s.arena = v;
       },
       [](const SceneSpec &s) { return s.arena; }},
      {"path", "straight, turn, square, odo_a, odo_b, avoid or a script (F/B/L/R/S moves)",
       [](SceneSpec &s, const std::string &v) {
         if (v != "avoid") path_script(v, 36, 90, 36, true);  // validates
         s.path = v;
       },
       [](const SceneSpec &s) { return s.path; }},
      real_key("length", &SceneSpec::length_in, -kMaxPathIn, kMaxPathIn, "in"),
      real_key("angle", &SceneSpec::angle_deg, -kMaxTurnDeg, kMaxTurnDeg, "deg"),
      real_key("side", &SceneSpec::side_in, 0.01, kMaxPathIn, "in"),
      {"dir", "left or right",
       [](SceneSpec &s, const std::string &v) {
         if (v != "left" && v != "right") spec_error("dir", "expected left or right, not '" + v + "'");
         s.square_left = v == "left";
       },
       [](const SceneSpec &s) { return std::string(s.square_left ? "left" : "right"); }},
      {"size", "WxH, 2.." + std::to_string(kMaxFrameDim) + " a side",
       [](SceneSpec &s, const std::string &v) {
         const auto x = v.find('x');
         if (x == std::string::npos) spec_error("size", "expected WxH (e.g. 160x120), not '" + v + "'");
         s.width = int(parse_int("size", v.substr(0, x), 2, kMaxFrameDim));
         s.height = int(parse_int("size", v.substr(x + 1), 2, kMaxFrameDim));
       },
       [](const SceneSpec &s) { return size_name(s.width, s.height); }},
      {"frames", "1.." + std::to_string(kMaxFrames) + " or auto",
       [](SceneSpec &s, const std::string &v) {
         s.frames = v == "auto" ? 0 : int(parse_int("frames", v, 1, kMaxFrames));
       },
       [](const SceneSpec &s) { return s.frames ? std::to_string(s.frames) : std::string("auto"); }},
      {"seed", "0.." + std::to_string(kMaxSceneSeed),
       [](SceneSpec &s, const std::string &v) { s.seed = uint64_t(parse_int("seed", v, 0, kMaxSceneSeed)); },
       [](const SceneSpec &s) { return std::to_string(s.seed); }},
      real_key("noise", &SceneSpec::noise, 0, 100, "levels"),
      real_key("speed", &SceneSpec::speed_in, 0.001, 12, "in per frame"),
      real_key("turn_rate", &SceneSpec::turn_rate_deg, 0.001, 90, "deg per frame"),
      {"fx", num(kMinFxPerWidth) + ".." + num(kMaxFxPerWidth) + " x width px, or auto",
       [](SceneSpec &s, const std::string &v) {
         // The width may come later in the spec: the ratio is checked once all keys are read.
         s.fx = v == "auto" ? 0 : parse_num("fx", v, 0.01, kMaxFxPerWidth * kMaxFrameDim);
       },
       [](const SceneSpec &s) { return s.fx > 0 ? num(s.fx) : std::string("auto"); }},
      real_key("cam_height", &SceneSpec::cam_height_in, 0.5, 36, "in"),
      real_key("tilt", &SceneSpec::tilt_deg, -60, 80, "deg"),
      real_key("cam_offset", &SceneSpec::cam_offset_in, -12, 12, "in"),
      int_key("ss", &SceneSpec::supersample, 1, 8, ""),
      {"mover", "none, cross or arena",
       [](SceneSpec &s, const std::string &v) {
         if (v != "none" && v != "cross" && v != "arena")
           spec_error("mover", "expected none, cross or arena, not '" + v + "'");
         s.mover = v;
       },
       [](const SceneSpec &s) { return s.mover; }},
      real_key("flicker", &SceneSpec::flicker, 0, 0.9, ""),
      int_key("flicker_period", &SceneSpec::flicker_period, 2, kMaxFrames, "frames"),
      {"light_step", "0.." + std::to_string(kMaxFrames) + " or none",
       [](SceneSpec &s, const std::string &v) {
         s.light_step = v == "none" ? -1 : int(parse_int("light_step", v, 0, kMaxFrames));
       },
       [](const SceneSpec &s) {
         return s.light_step < 0 ? std::string("none") : std::to_string(s.light_step);
       }},
      real_key("step_gain", &SceneSpec::step_gain, 0, 10, ""),
      real_key("step_offset", &SceneSpec::step_offset, -255, 255, "levels"),
      real_key("slip", &SceneSpec::slip, 0, 1, ""),
      real_key("enc_noise", &SceneSpec::enc_noise, 0, 100, "ticks"),
      real_key("tpi", &SceneSpec::tpi, 1, 10000, "ticks per in"),
      real_key("wheelbase", &SceneSpec::wheelbase_in, 0.5, 60, "in"),
      real_key("radius", &SceneSpec::radius_in, 0.1, 60, "in"),
      real_key("block_dist", &SceneSpec::block_dist_in, 0, kMaxPathIn, "in"),
      {"start", "X:Y:HEADING, X and Y -" + num(kMaxPathIn) + ".." + num(kMaxPathIn) + " in, HEADING -360..360 deg, or arena",
       [](SceneSpec &s, const std::string &v) {
         if (v == "arena") {
           s.has_start = false;
           return;
         }
         const auto a = v.find(':'), b = v.find(':', a == std::string::npos ? a : a + 1);
         if (a == std::string::npos || b == std::string::npos)
           spec_error("start", "expected X:Y:HEADING or arena, not '" + v + "'");
         s.start = {parse_num("start", v.substr(0, a), -kMaxPathIn, kMaxPathIn),
                    parse_num("start", v.substr(a + 1, b - a - 1), -kMaxPathIn, kMaxPathIn),
                    parse_num("start", v.substr(b + 1), -360, 360)};
         s.has_start = true;
       },
       [](const SceneSpec &s) {
         return s.has_start ? num(s.start.x_in) + ":" + num(s.start.y_in) + ":" + num(s.start.heading_deg)
                            : std::string("arena");
       }},
      {"texture_seed", "0.." + std::to_string(kMaxTextureSeed) + " or arena",
       [](SceneSpec &s, const std::string &v) {
         s.has_texture_seed = v != "arena";
         if (s.has_texture_seed) s.texture_seed = uint64_t(parse_int("texture_seed", v, 0, kMaxTextureSeed));
       },
       [](const SceneSpec &s) {
         return s.has_texture_seed ? std::to_string(s.texture_seed) : std::string("arena");
       }},
      bool_key("uyvy", &SceneSpec::write_uyvy),
      bool_key("flow", &SceneSpec::write_flow),
      bool_key("rgb", &SceneSpec::write_rgb),
  };
  return keys;
}

}  // namespace

SceneSpec parse_scene_spec(const std::string &text) {
  SceneSpec s;
  std::map<std::string, bool> seen;
  size_t pos = 0;
  if (text.find_first_not_of(" \t") == std::string::npos) return s;
  while (pos <= text.size()) {
    size_t end = text.find(',', pos);
    if (end == std::string::npos) end = text.size();
    const std::string item = text.substr(pos, end - pos);
    pos = end + 1;
    if (item.empty()) throw InputError("scene spec: empty item (stray comma) in '" + text + "'");
    const auto eq = item.find('=');
    if (eq == std::string::npos)
      throw InputError("scene spec: '" + item + "' is not key=value");
    const std::string key = item.substr(0, eq), val = item.substr(eq + 1);
    const KeyDef *def = nullptr;
    for (const auto &k : spec_keys())
      if (key == k.name) def = &k;
    if (!def) {
      std::string known;
      for (const auto &k : spec_keys()) known += (known.empty() ? "" : " ") + std::string(k.name);
      throw InputError("scene spec: unknown key '" + key + "' (known: " + known + ")");
    }
    if (seen[key]) throw InputError("scene spec: key '" + key + "' given twice");
    seen[key] = true;
    def->set(s, val);
  }
  if (s.write_uyvy && s.width % 2)
    throw InputError("scene spec: size: UYVY needs an even width (or set uyvy=0)");
  if (s.fx > 0 && (s.fx < kMinFxPerWidth * s.width || s.fx > kMaxFxPerWidth * s.width))
    spec_error("fx", num(s.fx) + " is out of range " + num(kMinFxPerWidth * s.width) + ".." +
                         num(kMaxFxPerWidth * s.width) + " (" + num(kMinFxPerWidth) + ".." +
                         num(kMaxFxPerWidth) + " x the width " + std::to_string(s.width) + ")");
  return s;
}

std::string scene_spec_ranges() {
  std::string out;
  for (const auto &k : spec_keys()) out += "  " + std::string(k.name) + ": " + k.range + "\n";
  return out;
}

std::string format_scene_spec(const SceneSpec &s) {
  std::string out;
  for (const auto &k : spec_keys()) out += (out.empty() ? "" : ",") + std::string(k.name) + "=" + k.get(s);
  return out;
}

// ---------------------------------------------------------------------------------------------
// Generator

Camera scene_camera(const SceneSpec &s) {
  Camera c = Camera::standard(s.width, s.height);
  if (s.fx > 0) c.fx = c.fy = s.fx;
  c.cam_height_in = s.cam_height_in;
  c.tilt_deg = s.tilt_deg;
  c.cam_offset_in = s.cam_offset_in;
  return c;
}

SceneGenerator::SceneGenerator(const SceneSpec &spec) : spec_(spec) { init(load_arena(spec.arena)); }

SceneGenerator::SceneGenerator(const SceneSpec &spec, const World &arena) : spec_(spec) { init(arena); }

void SceneGenerator::init(const World &arena) {
  cam_ = scene_camera(spec_);
  arena_ = arena;
  if (spec_.has_texture_seed) arena_.texture_seed = spec_.texture_seed;
  const Pose start = spec_.has_start ? spec_.start : arena_.start;
  if (spec_.mover == "none") {
    arena_.movers.clear();
  } else if (spec_.mover == "cross") {
    const double h = deg2rad(start.heading_deg);
    const Vec2 f{std::cos(h), std::sin(h)}, l{-std::sin(h), std::cos(h)};
    MoverDef m;
    m.cylinder = true;
    m.size_in = 2.5;
    m.height_in = 5;
    m.color = {150, 25, 25};
    m.a = {start.x_in + 30 * f.x - 12 * l.x, start.y_in + 30 * f.y - 12 * l.y};
    m.b = {start.x_in + 30 * f.x + 12 * l.x, start.y_in + 30 * f.y + 12 * l.y};
    m.speed_in = 0.4;
    arena_.movers = {m};
  } else if (arena_.movers.empty()) {
    throw InputError("scene spec: mover=arena but arena '" + arena_.name + "' defines no mover");
  }
  finalize_world(arena_);
  if (spec_.path == "avoid") {
    script_ = "avoid";
  } else {
    script_ = path_script(spec_.path, spec_.length_in, spec_.angle_deg, spec_.side_in, spec_.square_left);
    steps_ = expand_script(script_, spec_.speed_in, spec_.turn_rate_deg);
  }
  if (spec_.frames <= 0) spec_.frames = script_ == "avoid" ? 300 : int(std::min<size_t>(steps_.size() + 1, kMaxFrames));
  enc_model_.ticks_per_inch = spec_.tpi;
  enc_model_.wheelbase_in = spec_.wheelbase_in;
  enc_model_.slip = spec_.slip;
  enc_model_.noise_ticks = spec_.enc_noise;
  pose_ = start;
}

RenderOptions SceneGenerator::render_options() const {
  RenderOptions o;
  o.supersample = spec_.supersample;
  double g = 1 + spec_.flicker * std::sin(2 * kPi * frame_ / spec_.flicker_period);
  double off = 0;
  if (spec_.light_step >= 0 && frame_ >= spec_.light_step) {
    g *= spec_.step_gain;
    off = spec_.step_offset;
  }
  o.gain = g;
  o.offset = off;
  o.noise_sigma = spec_.noise;
  o.noise_seed = hash_key(spec_.seed, uint64_t(frame_), 0x6e6f697365ull);
  return o;
}

RenderResult SceneGenerator::render() const {
  return bvb::render(world_now(), pose_, cam_, render_options());
}

ColumnTruth SceneGenerator::columns() const { return column_truth(world_now(), pose_, cam_); }

FrameTruth SceneGenerator::truth() const {
  const World w = world_now();
  FrameTruth t;
  t.frame = frame_;
  t.pose = pose_;
  t.step = last_step_;
  t.clearance_in = corridor_clearance(w, pose_, spec_.radius_in);
  t.blocked = t.clearance_in <= spec_.block_dist_in;
  t.collision = collides(w, pose_, spec_.radius_in);
  t.left_ticks = enc_.left_ticks();
  t.right_ticks = enc_.right_ticks();
  const RenderOptions o = render_options();
  t.gain = o.gain;
  t.offset = o.offset;
  return t;
}

Step SceneGenerator::next_step() {
  if (script_ != "avoid") return size_t(frame_) < steps_.size() ? steps_[size_t(frame_)] : Step{};
  const World w = world_now();
  const double R = spec_.radius_in, D = spec_.block_dist_in;
  const double clear = corridor_clearance(w, pose_, R);
  if (avoid_dir_ != 0) {
    // Turn until the way is clearly free; after a full circle settle for just free.
    avoid_turned_ += spec_.turn_rate_deg;
    const double need = avoid_turned_ >= 360 ? D : D + 6;
    if (clear <= need) return {0, avoid_dir_ * spec_.turn_rate_deg};
    avoid_dir_ = 0;
  }
  if (clear > D) return {std::min(spec_.speed_in, clear), 0};
  Pose l = pose_, r = pose_;
  l.heading_deg += 45;
  r.heading_deg -= 45;
  avoid_dir_ = corridor_clearance(w, l, R) >= corridor_clearance(w, r, R) ? 1 : -1;
  avoid_turned_ = 0;
  return {0, avoid_dir_ * spec_.turn_rate_deg};
}

Step SceneGenerator::drive_step(Drive d) const {
  switch (d) {
    case Drive::Forward: return {spec_.speed_in, 0};
    case Drive::Left: return {0, spec_.turn_rate_deg};
    case Drive::Right: return {0, -spec_.turn_rate_deg};
    case Drive::Stop: break;
  }
  return {};
}

bool SceneGenerator::advance(const Step &step, bool stop_at_obstacles) {
  const Pose next = step_pose(pose_, step.forward_in, step.turn_deg);
  bool moved = true;
  if (stop_at_obstacles && step.forward_in != 0 &&
      collides(world_at_frame(arena_, frame_ + 1), next, spec_.radius_in))
    moved = false;
  encoders_step(enc_, enc_model_, step, hash_key(spec_.seed, uint64_t(frame_ + 1), 0x656e63ull));
  ++frame_;
  if (moved) pose_ = next;
  last_step_ = moved ? step : Step{};
  return moved;
}

// ---------------------------------------------------------------------------------------------
// Writing

namespace {

std::string frame_name(const char *stem, int k, const char *ext) {
  char b[64];
  std::snprintf(b, sizeof b, "%s_%04d.%s", stem, k, ext);
  return b;
}

std::string fixed(double v, int digits) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char b[64];
  std::snprintf(b, sizeof b, "%.*f", digits, v);
  return b;
}

const char *kTruthHeader =
    "frame,x_in,y_in,heading_deg,step_fwd_in,step_turn_deg,blocked,clearance_in,collision,"
    "left_ticks,right_ticks,gain,offset";
const char *kColumnsHeader = "frame,column,distance_in,boundary_row";

// Is `name` one of the files write_scene writes? frame_NNNN.pgm/.uyvy/.ppm, flow_NNNN.flo
// (4 or more digits) and the four text files.
bool scene_file_name(const std::string &name) {
  for (const char *fixed_name : {"scene.txt", "arena.txt", "truth.csv", "columns.csv"})
    if (name == fixed_name) return true;
  auto numbered = [&](const std::string &stem, const std::string &ext) {
    if (name.size() < stem.size() + 4 + ext.size() || name.compare(0, stem.size(), stem) != 0 ||
        name.compare(name.size() - ext.size(), ext.size(), ext) != 0)
      return false;
    const std::string digits = name.substr(stem.size(), name.size() - stem.size() - ext.size());
    return digits.find_first_not_of("0123456789") == std::string::npos;
  };
  return numbered("frame_", ".pgm") || numbered("frame_", ".uyvy") || numbered("frame_", ".ppm") ||
         numbered("flow_", ".flo");
}

// --force replaces a scene and nothing else: a directory holding anything a scene does not
// write (a user's notes, a subdirectory, a link) is refused whole, so nothing of theirs is lost.
void check_replaceable(const fs::path &out) {
  std::error_code ec;
  const auto st = fs::symlink_status(out, ec);
  if (fs::is_symlink(st)) throw InputError(out.string() + ": is a symbolic link; not replacing it");
  if (!fs::is_directory(st)) throw InputError(out.string() + ": exists and is not a directory; not replacing it");
  if (fs::is_empty(out, ec)) return;
  if (!fs::is_regular_file(fs::symlink_status(out / "scene.txt", ec)))
    throw InputError(out.string() + ": exists and is not a scene directory (no scene.txt); not replacing it");
  for (const auto &e : fs::directory_iterator(out, ec)) {
    const std::string name = e.path().filename().string();
    if (!fs::is_regular_file(e.symlink_status(ec)) || !scene_file_name(name))
      throw InputError(out.string() + ": holds '" + name +
                       "', which a scene does not write; not replacing it (move it away or choose another --out)");
  }
  if (ec) throw InputError(out.string() + ": cannot list: " + ec.message());
}

void write_text(const fs::path &p, const std::string &s) {
  write_file_atomic(p.string(), s.data(), s.size());
}

std::string scene_txt(const SceneGenerator &g) {
  const Camera &c = g.camera();
  const SceneSpec &s = g.spec();
  std::string files = "pgm";
  if (s.write_uyvy) files += " uyvy";
  if (s.write_rgb) files += " ppm";
  if (s.write_flow) files += " flo";
  std::string t;
  t += "# bvb scene: rendered frames with ground truth (file formats: harness/scene/scene_io.h)\n";
  t += "format = bvb-scene-1\n";
  t += "spec = " + format_scene_spec(s) + "\n";
  t += "arena = " + g.arena().name + "\n";
  t += "frames = " + std::to_string(s.frames) + "\n";
  t += "width = " + std::to_string(c.width) + "\n";
  t += "height = " + std::to_string(c.height) + "\n";
  t += "fx = " + num(c.fx) + "\n";
  t += "fy = " + num(c.fy) + "\n";
  t += "cx = " + num(c.cx) + "\n";
  t += "cy = " + num(c.cy) + "\n";
  t += "cam_height_in = " + num(c.cam_height_in) + "\n";
  t += "tilt_deg = " + num(c.tilt_deg) + "\n";
  t += "cam_offset_in = " + num(c.cam_offset_in) + "\n";
  t += "script = " + g.script() + "\n";
  t += "files = " + files + "\n";
  t += "units = inches, degrees; world z up, heading counter-clockwise from +x; image x right, "
       "y down, pixel centres at integers\n";
  t += "yuv = BT.601 studio range: Y = ((66R+129G+25B+128)>>8)+16, U = ((-38R-74G+112B+128)>>8)"
       "+128, V = ((112R-94G-18B+128)>>8)+128, U and V of a pair (a+b+1)>>1; pgm = Y\n";
  return t;
}

}  // namespace

std::string SceneData::file(const char *stem, int k, const char *ext) const {
  return (fs::path(dir) / frame_name(stem, k, ext)).string();
}

void write_scene(const SceneSpec &spec, const std::string &dir, bool replace) {
  if (dir.empty()) throw InputError("scene: empty output directory name");
  SceneGenerator g(spec);
  fs::path out = fs::path(dir);
  if (!out.has_filename()) out = out.parent_path();
  std::error_code ec;
  if (fs::exists(fs::symlink_status(out, ec))) {
    if (!replace) throw InputError(out.string() + ": already exists (use --force to replace a scene)");
    check_replaceable(out);
  }
  if (out.has_parent_path()) fs::create_directories(out.parent_path(), ec);
  const fs::path tmp = out.string() + ".tmp." + std::to_string(getpid());
  fs::remove_all(tmp, ec);
  if (!fs::create_directory(tmp, ec))
    throw InputError(tmp.string() + ": cannot create directory: " + ec.message());
  try {
    const SceneSpec &s = g.spec();
    write_text(tmp / "scene.txt", scene_txt(g));
    write_text(tmp / "arena.txt", format_arena(g.arena()));
    std::string truth = std::string(kTruthHeader) + "\n";
    std::string cols = std::string(kColumnsHeader) + "\n";
    RenderResult prev;
    World prev_world;
    Pose prev_pose;
    for (int k = 0; k < s.frames; ++k) {
      const World w = g.world_now();
      RenderResult r = g.render();
      write_pnm((tmp / frame_name("frame", k, "pgm")).string(), r.grey);
      if (s.write_uyvy) write_file_atomic((tmp / frame_name("frame", k, "uyvy")).string(), r.uyvy);
      if (s.write_rgb) write_pnm((tmp / frame_name("frame", k, "ppm")).string(), r.rgb);
      if (s.write_flow && k > 0)
        write_flo((tmp / frame_name("flow", k - 1, "flo")).string(),
                  true_flow(prev_world, prev_pose, prev, w, g.pose(), r, g.camera()));
      const FrameTruth t = g.truth();
      truth += std::to_string(k) + "," + fixed(t.pose.x_in, 6) + "," + fixed(t.pose.y_in, 6) + "," +
               fixed(t.pose.heading_deg, 6) + "," + fixed(t.step.forward_in, 6) + "," +
               fixed(t.step.turn_deg, 6) + "," + (t.blocked ? "1" : "0") + "," +
               fixed(t.clearance_in, 4) + "," + (t.collision ? "1" : "0") + "," +
               std::to_string(t.left_ticks) + "," + std::to_string(t.right_ticks) + "," +
               fixed(t.gain, 6) + "," + fixed(t.offset, 6) + "\n";
      const ColumnTruth c = g.columns();
      for (int x = 0; x < s.width; ++x)
        cols += std::to_string(k) + "," + std::to_string(x) + "," +
                fixed(c.distance_in[size_t(x)], 4) + "," + std::to_string(c.boundary_row[size_t(x)]) + "\n";
      if (s.write_flow) {
        prev = std::move(r);
        prev_world = w;
        prev_pose = g.pose();
      }
      if (k + 1 < s.frames) g.advance();
    }
    write_text(tmp / "truth.csv", truth);
    write_text(tmp / "columns.csv", cols);
    // Read back before it takes the name: a scene its own reader rejects is never left behind.
    read_scene(tmp.string());
    if (fs::exists(out, ec)) {
      const fs::path old = out.string() + ".old." + std::to_string(getpid());
      fs::rename(out, old);
      fs::rename(tmp, out);
      fs::remove_all(old, ec);
    } else {
      fs::rename(tmp, out);
    }
  } catch (const fs::filesystem_error &e) {
    fs::remove_all(tmp, ec);
    throw InputError(out.string() + ": " + e.code().message());
  } catch (...) {
    fs::remove_all(tmp, ec);
    throw;
  }
}

// ---------------------------------------------------------------------------------------------
// Reading

namespace {

std::string read_text(const fs::path &p) {
  auto b = read_file(p.string());
  return std::string(b.begin(), b.end());
}

struct CsvCursor {
  std::string where;
  int line = 0;
  [[noreturn]] void fail(const std::string &m) const {
    throw InputError(where + ":" + std::to_string(line) + ": " + m);
  }
  double real(const std::string &s, const char *what, bool allow_inf = false) const {
    if (allow_inf && s == "inf") return kInf;
    errno = 0;
    char *e = nullptr;
    const double v = std::strtod(s.c_str(), &e);
    if (s.empty() || *e != '\0' || errno == ERANGE || !std::isfinite(v) ||
        s.find_first_of("xXpPnN") != std::string::npos)
      fail(std::string(what) + ": not a number: '" + s + "'");
    return v;
  }
  long long integer(const std::string &s, const char *what) const {
    const size_t start = (!s.empty() && s[0] == '-') ? 1 : 0;
    if (s.size() <= start || s.size() > 20 || s.find_first_not_of("0123456789", start) != std::string::npos)
      fail(std::string(what) + ": not a whole number: '" + s + "'");
    // 19 digits can exceed 64 bits: strtoll says so rather than throwing as stoll does.
    errno = 0;
    const long long v = std::strtoll(s.c_str(), nullptr, 10);
    if (errno == ERANGE) fail(std::string(what) + ": out of range: '" + s + "'");
    return v;
  }
};

std::vector<std::string> split(const std::string &line) {
  std::vector<std::string> f;
  size_t pos = 0;
  for (;;) {
    const size_t e = line.find(',', pos);
    f.push_back(line.substr(pos, e == std::string::npos ? std::string::npos : e - pos));
    if (e == std::string::npos) break;
    pos = e + 1;
  }
  return f;
}

// Lines without the trailing '\r' of files edited elsewhere.
std::vector<std::string> lines_of(const std::string &text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) {
    if (!l.empty() && l.back() == '\r') l.pop_back();
    out.push_back(l);
  }
  return out;
}

}  // namespace

void parse_scene_txt(const std::string &text, const std::string &where, SceneData *d) {
  std::map<std::string, std::string> kv;
  const std::vector<std::string> known = {"format", "spec",  "arena", "frames", "width",
                                          "height", "fx",    "fy",    "cx",     "cy",
                                          "cam_height_in", "tilt_deg", "cam_offset_in",
                                          "script", "files", "units", "yuv"};
  int ln = 0;
  for (const auto &l : lines_of(text)) {
    ++ln;
    const auto first = l.find_first_not_of(" \t");
    if (first == std::string::npos || l[first] == '#') continue;
    const auto eq = l.find(" = ");
    if (eq == std::string::npos) throw InputError(where + ":" + std::to_string(ln) + ": expected 'key = value'");
    const std::string key = l.substr(first, eq - first), val = l.substr(eq + 3);
    if (std::find(known.begin(), known.end(), key) == known.end())
      throw InputError(where + ":" + std::to_string(ln) + ": unknown key '" + key + "'");
    if (kv.count(key)) throw InputError(where + ":" + std::to_string(ln) + ": key '" + key + "' given twice");
    kv[key] = val;
  }
  for (const char *req : {"format", "spec", "frames", "width", "height", "fx", "fy", "cx", "cy",
                          "cam_height_in", "tilt_deg", "cam_offset_in", "files"})
    if (!kv.count(req)) throw InputError(where + ": missing '" + req + "'");
  if (kv["format"] != "bvb-scene-1")
    throw InputError(where + ": unsupported format '" + kv["format"] + "' (expected bvb-scene-1)");
  try {
    d->spec = parse_scene_spec(kv["spec"]);
  } catch (const InputError &e) {
    throw InputError(where + ": " + e.what());
  }
  CsvCursor sc{where, 0};
  d->frames = int(sc.integer(kv["frames"], "frames"));
  d->camera = Camera::standard(int(sc.integer(kv["width"], "width")), int(sc.integer(kv["height"], "height")));
  if (d->frames < 1 || d->frames > kMaxFrames) throw InputError(where + ": frames out of range");
  if (d->camera.width != d->spec.width || d->camera.height != d->spec.height)
    throw InputError(where + ": width/height disagree with the spec's size");
  if (d->spec.frames != d->frames) throw InputError(where + ": frames disagrees with the spec");
  d->camera.fx = sc.real(kv["fx"], "fx");
  d->camera.fy = sc.real(kv["fy"], "fy");
  d->camera.cx = sc.real(kv["cx"], "cx");
  d->camera.cy = sc.real(kv["cy"], "cy");
  d->camera.cam_height_in = sc.real(kv["cam_height_in"], "cam_height_in");
  d->camera.tilt_deg = sc.real(kv["tilt_deg"], "tilt_deg");
  d->camera.cam_offset_in = sc.real(kv["cam_offset_in"], "cam_offset_in");
  if (!(d->camera.fx > 0) || !(d->camera.fy > 0)) throw InputError(where + ": fx and fy must be > 0");
  std::istringstream fl(kv["files"]);
  bool pgm = false;
  for (std::string f; fl >> f;) {
    if (f == "pgm") pgm = true;
    else if (f == "uyvy") d->has_uyvy = true;
    else if (f == "ppm") d->has_rgb = true;
    else if (f == "flo") d->has_flow = true;
    else throw InputError(where + ": files: unknown kind '" + f + "'");
  }
  if (!pgm) throw InputError(where + ": files: 'pgm' missing");
}

std::vector<FrameTruth> parse_truth_csv(const std::string &text, const std::string &where) {
  CsvCursor c{where, 0};
  const auto lines = lines_of(text);
  if (lines.empty() || lines[0] != kTruthHeader) {
    c.line = 1;
    c.fail(std::string("expected the header '") + kTruthHeader + "'");
  }
  std::vector<FrameTruth> truth;
  for (size_t i = 1; i < lines.size(); ++i) {
    c.line = int(i + 1);
    if (lines[i].empty()) continue;
    const auto f = split(lines[i]);
    if (f.size() != 13) c.fail("expected 13 fields, found " + std::to_string(f.size()));
    FrameTruth t;
    t.frame = int(c.integer(f[0], "frame"));
    if (t.frame != int(truth.size())) c.fail("frame " + f[0] + " out of sequence");
    t.pose = {c.real(f[1], "x_in"), c.real(f[2], "y_in"), c.real(f[3], "heading_deg")};
    t.step = {c.real(f[4], "step_fwd_in"), c.real(f[5], "step_turn_deg")};
    if (f[6] != "0" && f[6] != "1") c.fail("blocked must be 0 or 1");
    t.blocked = f[6] == "1";
    t.clearance_in = c.real(f[7], "clearance_in", true);
    if (f[8] != "0" && f[8] != "1") c.fail("collision must be 0 or 1");
    t.collision = f[8] == "1";
    t.left_ticks = c.integer(f[9], "left_ticks");
    t.right_ticks = c.integer(f[10], "right_ticks");
    t.gain = c.real(f[11], "gain");
    t.offset = c.real(f[12], "offset");
    truth.push_back(t);
  }
  return truth;
}

std::vector<ColumnTruth> parse_columns_csv(const std::string &text, const std::string &where, int frames,
                                           int width, int height) {
  CsvCursor c{where, 0};
  const auto lines = lines_of(text);
  if (lines.empty() || lines[0] != kColumnsHeader) {
    c.line = 1;
    c.fail(std::string("expected the header '") + kColumnsHeader + "'");
  }
  if (frames < 1 || width < 1 || height < 1) throw InputError(where + ": no frames or an empty image to hold columns");
  const int W = width, H = height;
  std::vector<ColumnTruth> columns(size_t(frames), ColumnTruth{});
  size_t expect = 0;
  for (size_t i = 1; i < lines.size(); ++i) {
    c.line = int(i + 1);
    if (lines[i].empty()) continue;
    const auto f = split(lines[i]);
    if (f.size() != 4) c.fail("expected 4 fields, found " + std::to_string(f.size()));
    const long long k = c.integer(f[0], "frame"), x = c.integer(f[1], "column");
    if (k != (long long)(expect / size_t(W)) || x != (long long)(expect % size_t(W)))
      c.fail("expected frame " + std::to_string(expect / size_t(W)) + " column " +
             std::to_string(expect % size_t(W)));
    if (k >= frames) c.fail("more rows than frames x width");
    const double dist = c.real(f[2], "distance_in", true);
    const long long row = c.integer(f[3], "boundary_row");
    if (row < -1 || row >= H) c.fail("boundary_row out of range -1.." + std::to_string(H - 1));
    auto &col = columns[size_t(k)];
    col.distance_in.push_back(dist);
    col.boundary_row.push_back(int(row));
    ++expect;
  }
  if (expect != size_t(frames) * size_t(W))
    throw InputError(where + ": " + std::to_string(expect) + " rows, expected frames x width = " +
                     std::to_string(size_t(frames) * size_t(W)));
  return columns;
}

SceneData read_scene(const std::string &dir) {
  SceneData d;
  d.dir = dir;
  const fs::path root(dir);
  std::error_code ec;
  if (!fs::is_directory(root, ec)) throw InputError(dir + ": not a directory");
  parse_scene_txt(read_text(root / "scene.txt"), (root / "scene.txt").string(), &d);
  d.arena = parse_arena(read_text(root / "arena.txt"), (root / "arena.txt").string());
  const std::string truth_csv = (root / "truth.csv").string();
  d.truth = parse_truth_csv(read_text(truth_csv), truth_csv);
  if (int(d.truth.size()) != d.frames)
    throw InputError(truth_csv + ": " + std::to_string(d.truth.size()) + " frames, scene.txt says " +
                     std::to_string(d.frames));
  const std::string columns_csv = (root / "columns.csv").string();
  d.columns = parse_columns_csv(read_text(columns_csv), columns_csv, d.frames, d.camera.width, d.camera.height);

  for (int k = 0; k < d.frames; ++k) {
    std::vector<std::string> need = {d.file("frame", k, "pgm")};
    if (d.has_uyvy) need.push_back(d.file("frame", k, "uyvy"));
    if (d.has_rgb) need.push_back(d.file("frame", k, "ppm"));
    if (d.has_flow && k + 1 < d.frames) need.push_back(d.file("flow", k, "flo"));
    for (const auto &p : need)
      if (!fs::is_regular_file(p, ec)) throw InputError(p + ": missing (scene.txt lists it)");
  }
  return d;
}

Image SceneData::grey(int k) const {
  if (k < 0 || k >= frames) throw InputError(dir + ": no frame " + std::to_string(k));
  Image g = read_pnm(file("frame", k, "pgm"));
  if (g.width != camera.width || g.height != camera.height || g.channels != 1)
    throw InputError(file("frame", k, "pgm") + ": not a " + size_name(camera.width, camera.height) + " grey image");
  return g;
}

std::vector<uint8_t> SceneData::uyvy(int k) const {
  if (!has_uyvy || k < 0 || k >= frames) throw InputError(dir + ": no UYVY frame " + std::to_string(k));
  return read_uyvy(file("frame", k, "uyvy"), camera.width, camera.height);
}

Image SceneData::rgb(int k) const {
  if (!has_rgb || k < 0 || k >= frames) throw InputError(dir + ": no RGB frame " + std::to_string(k));
  Image g = read_pnm(file("frame", k, "ppm"));
  if (g.width != camera.width || g.height != camera.height || g.channels != 3)
    throw InputError(file("frame", k, "ppm") + ": not a " + size_name(camera.width, camera.height) + " RGB image");
  return g;
}

FlowField SceneData::flow(int k) const {
  if (!has_flow || k < 0 || k + 1 >= frames) throw InputError(dir + ": no flow for frame " + std::to_string(k));
  FlowField f = read_flo(file("flow", k, "flo"));
  if (f.width != camera.width || f.height != camera.height)
    throw InputError(file("flow", k, "flo") + ": flow size differs from the frames'");
  return f;
}

}  // namespace bvb
