#include "world.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <list>
#include <map>
#include <mutex>
#include <sstream>


#include "io.h"
#include "rng.h"

namespace bvb {

namespace fs = std::filesystem;

// ---------------------------------------------------------------------------------------------
// Geometry of obstacles

void Obstacle::finalize() {
  switch (kind) {
    case ObstacleKind::Wall: {
      const Vec2 a{p[0], p[1]}, b{p[2], p[3]};
      const double len = std::hypot(b.x - a.x, b.y - a.y);
      const double dx = (b.x - a.x) / len, dy = (b.y - a.y) / len, h = p[4] * 0.5;
      const Vec2 n{-dy * h, dx * h};
      corners = {Vec2{a.x - n.x, a.y - n.y}, Vec2{b.x - n.x, b.y - n.y},
                 Vec2{b.x + n.x, b.y + n.y}, Vec2{a.x + n.x, a.y + n.y}};
      centre = {(a.x + b.x) * 0.5, (a.y + b.y) * 0.5};
      radius = 0;
      break;
    }
    case ObstacleKind::Box: {
      const double r = deg2rad(p[4]), hx = p[2] * 0.5, hy = p[3] * 0.5;
      const Vec2 c{p[0], p[1]}, ax{std::cos(r), std::sin(r)}, ay{-std::sin(r), std::cos(r)};
      auto at = [&](double sx, double sy) {
        return Vec2{c.x + sx * hx * ax.x + sy * hy * ay.x, c.y + sx * hx * ax.y + sy * hy * ay.y};
      };
      corners = {at(-1, -1), at(1, -1), at(1, 1), at(-1, 1)};
      centre = c;
      radius = 0;
      break;
    }
    case ObstacleKind::Cylinder:
      centre = {p[0], p[1]};
      radius = p[2];
      break;
  }
}

Vec2 MoverDef::position(int frame) const {
  const double len = std::hypot(b.x - a.x, b.y - a.y);
  if (len <= 0 || speed_in <= 0) return a;
  double s = std::fmod(speed_in * frame, 2 * len);
  if (s > len) s = 2 * len - s;
  const double f = s / len;
  return {a.x + (b.x - a.x) * f, a.y + (b.y - a.y) * f};
}

// ---------------------------------------------------------------------------------------------
// Texture

namespace {

constexpr int kTextureSize = 1024;  // 128 in period at 0.125 in per texel

double smooth(double t) { return t * t * (3 - 2 * t); }

// Tileable value noise with `cells` lattice cells across the texture, values in [-1, 1].
void add_value_noise(std::vector<float> &tex, int n, int cells, double amp, uint64_t seed) {
  std::vector<double> lat(size_t(cells) * cells);
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i)
      lat[size_t(j) * cells + i] = double(hash_key(seed, uint64_t(i), uint64_t(j)) >> 11) *
                                       (2.0 / 9007199254740992.0) -
                                   1.0;
  const double scale = double(cells) / n;
  for (int y = 0; y < n; ++y) {
    const double fy = (y + 0.5) * scale;
    const int j0 = int(fy) % cells, j1 = (j0 + 1) % cells;
    const double ty = smooth(fy - std::floor(fy));
    for (int x = 0; x < n; ++x) {
      const double fx = (x + 0.5) * scale;
      const int i0 = int(fx) % cells, i1 = (i0 + 1) % cells;
      const double tx = smooth(fx - std::floor(fx));
      const double a = lat[size_t(j0) * cells + i0], b = lat[size_t(j0) * cells + i1];
      const double c = lat[size_t(j1) * cells + i0], d = lat[size_t(j1) * cells + i1];
      const double v = (a + (b - a) * tx) + ((c + (d - c) * tx) - (a + (b - a) * tx)) * ty;
      tex[size_t(y) * n + x] += float(amp * v);
    }
  }
}

std::shared_ptr<const Texture> build_texture(uint64_t seed) {
  const int n = kTextureSize;
  auto t = std::make_shared<Texture>();
  t->size = n;
  t->texel_in = 0.125;
  std::vector<float> base(size_t(n) * n, 0.f);
  // Blotches of 8, 2 and 0.5 in and a fine grain give optical flow gradients at every scale
  // the camera sees, from 0.05 in per pixel at the bottom of the image to inches far away.
  add_value_noise(base, n, n / 64, 0.50, hash_key(seed, 1));
  add_value_noise(base, n, n / 16, 0.35, hash_key(seed, 2));
  add_value_noise(base, n, n / 4, 0.25, hash_key(seed, 3));
  SceneRng grain(hash_key(seed, 5));
  for (auto &v : base) v += float(0.3 * (2 * grain.uniform() - 1));
  double mean = 0, var = 0;
  for (float v : base) mean += v;
  mean /= double(base.size());
  for (float v : base) var += (v - mean) * (v - mean);
  const double sd = std::sqrt(var / double(base.size()));
  for (auto &v : base) v = float(std::clamp((v - mean) * (0.4 / sd), -1.0, 1.0));
  // Scattered rotated squares of 0.3-1 in, light or dark: sharp corners for feature trackers.
  SceneRng rng(hash_key(seed, 4));
  const int count = n * n / 120;
  for (int k = 0; k < count; ++k) {
    const double cx = rng.uniform() * n, cy = rng.uniform() * n;
    const double side = 2.4 + 5.6 * rng.uniform(), ang = rng.uniform() * kPi;
    const double val = (rng.uniform() < 0.5 ? -1 : 1) * (0.5 + 0.3 * rng.uniform());
    const double ca = std::cos(ang), sa = std::sin(ang), h = side * 0.5;
    const int r = int(std::ceil(h * 1.4143)) + 1;
    for (int dy = -r; dy <= r; ++dy)
      for (int dx = -r; dx <= r; ++dx) {
        const int x = int(std::floor(cx)) + dx, y = int(std::floor(cy)) + dy;
        const double px = x + 0.5 - cx, py = y + 0.5 - cy;
        const double lx = px * ca + py * sa, ly = -px * sa + py * ca;
        if (std::fabs(lx) <= h && std::fabs(ly) <= h)
          base[size_t((y % n + n) % n) * n + size_t((x % n + n) % n)] = float(val);
      }
  }
  t->levels.push_back(std::move(base));
  for (int s = n / 2; s >= 1; s /= 2) {
    const auto &up = t->levels.back();
    std::vector<float> lv(size_t(s) * s);
    for (int y = 0; y < s; ++y)
      for (int x = 0; x < s; ++x) {
        const size_t i = size_t(2 * y) * (2 * s) + 2 * x;
        lv[size_t(y) * s + x] = 0.25f * (up[i] + up[i + 1] + up[i + 2 * s] + up[i + 2 * s + 1]);
      }
    t->levels.push_back(std::move(lv));
  }
  return t;
}

}  // namespace

// Textures are cached by seed: every scene generator reads its arena again, and a texture takes
// tens of milliseconds to build. Only the most recently used seeds are kept (a texture is about
// 6 MB): a process that reads arenas of many seeds, such as a sweep over texture_seed or the
// arena fuzz target, kept every one for ever and grew past 2 GB. An evicted texture lives on
// while a World holds it.
std::shared_ptr<const Texture> make_texture(uint64_t seed) {
  static std::mutex mu;
  static std::list<std::pair<uint64_t, std::shared_ptr<const Texture>>> recent;  // newest first
  std::lock_guard<std::mutex> lock(mu);
  for (auto it = recent.begin(); it != recent.end(); ++it)
    if (it->first == seed) {
      recent.splice(recent.begin(), recent, it);
      return it->second;
    }
  recent.emplace_front(seed, build_texture(seed));
  if (recent.size() > kTextureCacheSeeds) recent.pop_back();
  return recent.front().second;
}

float Texture::sample(double u, double v, double lod) const {
  auto bilinear = [&](int k, double uu, double vv) {
    const int s = size >> k;
    const double scale = 1.0 / (texel_in * double(1 << k));
    const double fx = uu * scale - 0.5, fy = vv * scale - 0.5;
    const double flx = std::floor(fx), fly = std::floor(fy);
    const float tx = float(fx - flx), ty = float(fy - fly);
    const int64_t ix = int64_t(flx), iy = int64_t(fly);
    const int m = s - 1;
    const int x0 = int(ix & m), x1 = int((ix + 1) & m), y0 = int(iy & m), y1 = int((iy + 1) & m);
    const float *L = levels[size_t(k)].data();
    const float a = L[size_t(y0) * s + x0], b = L[size_t(y0) * s + x1];
    const float c = L[size_t(y1) * s + x0], d = L[size_t(y1) * s + x1];
    const float top = a + (b - a) * tx, bot = c + (d - c) * tx;
    return top + (bot - top) * ty;
  };
  const int top_level = int(levels.size()) - 1;
  if (!(lod > 0)) return bilinear(0, u, v);
  if (lod >= top_level) return levels.back()[0];
  const int l0 = int(lod);
  const float f = float(lod - l0);
  const float a = bilinear(l0, u, v), b = bilinear(l0 + 1, u, v);
  return a + (b - a) * f;
}

// ---------------------------------------------------------------------------------------------
// Arena files

namespace {

struct LineReader {
  const std::string &where;
  int line;
  std::vector<std::string> tok;

  [[noreturn]] void fail(const std::string &msg) const {
    throw InputError(where + ":" + std::to_string(line) + ": " + msg);
  }
  double num(size_t i, const char *what) const {
    const std::string &s = tok[i];
    errno = 0;
    char *end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(v))
      fail(std::string("'") + tok[0] + "': " + what + ": not a number: '" + s + "'");
    return v;
  }
  double positive(size_t i, const char *what) const {
    const double v = num(i, what);
    if (!(v > 0)) fail(std::string("'") + tok[0] + "': " + what + " must be > 0");
    return v;
  }
  Rgb color(size_t i) const {
    Rgb c;
    float *ch[3] = {&c.r, &c.g, &c.b};
    for (int k = 0; k < 3; ++k) {
      const double v = num(i + size_t(k), "colour");
      if (v < 0 || v > 255) fail(std::string("'") + tok[0] + "': colour components are 0..255");
      *ch[k] = float(v);
    }
    return c;
  }
  double contrast(size_t i) const {
    if (tok.size() <= i) return 0.2;
    const double v = num(i, "contrast");
    if (v < 0 || v > 1) fail(std::string("'") + tok[0] + "': contrast must be 0..1");
    return v;
  }
  void arity(size_t lo, size_t hi, const char *usage) const {
    const size_t n = tok.size() - 1;
    if (n < lo || n > hi) fail(std::string("expected: ") + usage);
  }
};

std::string fmt(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.10g", v);
  return b;
}
std::string fmt(const Rgb &c) { return fmt(c.r) + " " + fmt(c.g) + " " + fmt(c.b); }

}  // namespace

void finalize_world(World &w) {
  for (auto &o : w.obstacles) o.finalize();
  w.texture = make_texture(w.texture_seed);
}

World parse_arena(const std::string &text, const std::string &where) {
  World w = parse_arena_untextured(text, where);
  w.texture = make_texture(w.texture_seed);
  return w;
}

World parse_arena_untextured(const std::string &text, const std::string &where) {
  World w;
  bool have_start = false, seen_seed = false, seen_floor = false, seen_light = false,
       seen_bg = false, seen_name = false;
  std::istringstream in(text);
  std::string raw;
  int line = 0;
  while (std::getline(in, raw)) {
    ++line;
    const auto hash = raw.find('#');
    if (hash != std::string::npos) raw.resize(hash);
    LineReader r{where, line, {}};
    std::istringstream ls(raw);
    for (std::string t; ls >> t;) r.tok.push_back(t);
    if (r.tok.empty()) continue;
    const std::string &kw = r.tok[0];
    auto once = [&](bool &seen) {
      if (seen) r.fail("'" + kw + "' given twice");
      seen = true;
    };
    if (kw == "name") {
      r.arity(1, 1, "name NAME");
      once(seen_name);
      w.name = r.tok[1];
    } else if (kw == "texture_seed") {
      r.arity(1, 1, "texture_seed N");
      once(seen_seed);
      // Read as an integer, exactly: format_arena writes every seed a spec accepts in full.
      const std::string &t = r.tok[1];
      if (t.empty() || t.size() > 18 || t.find_first_not_of("0123456789") != std::string::npos)
        r.fail("texture_seed must be a whole number 0.." + std::to_string(kMaxTextureSeed) + ", not '" + t + "'");
      w.texture_seed = std::stoull(t);
    } else if (kw == "floor") {
      r.arity(4, 4, "floor R G B CONTRAST");
      once(seen_floor);
      w.floor_color = r.color(1);
      w.floor_contrast = r.contrast(4);
    } else if (kw == "background") {
      r.arity(3, 3, "background R G B");
      once(seen_bg);
      w.background = r.color(1);
    } else if (kw == "light") {
      r.arity(4, 4, "light AMBIENT DIFFUSE AZIMUTH_DEG ELEVATION_DEG");
      once(seen_light);
      w.light.ambient = r.num(1, "ambient");
      w.light.diffuse = r.num(2, "diffuse");
      w.light.azimuth_deg = r.num(3, "azimuth");
      w.light.elevation_deg = r.num(4, "elevation");
      if (w.light.ambient < 0 || w.light.diffuse < 0 || w.light.ambient + w.light.diffuse > 4)
        r.fail("light: ambient and diffuse must be >= 0 with a sum <= 4");
      if (w.light.elevation_deg < 0 || w.light.elevation_deg > 90)
        r.fail("light: elevation must be 0..90 degrees");
    } else if (kw == "start") {
      r.arity(3, 3, "start X Y HEADING_DEG");
      once(have_start);
      w.start = {r.num(1, "x"), r.num(2, "y"), r.num(3, "heading")};
    } else if (kw == "wall") {
      r.arity(9, 10, "wall X0 Y0 X1 Y1 HEIGHT THICKNESS R G B [CONTRAST]");
      Obstacle o;
      o.kind = ObstacleKind::Wall;
      for (int k = 0; k < 4; ++k) o.p[size_t(k)] = r.num(size_t(1 + k), "coordinate");
      if (std::hypot(o.p[2] - o.p[0], o.p[3] - o.p[1]) < 1e-6) r.fail("wall: zero length");
      o.height_in = r.positive(5, "height");
      o.p[4] = r.positive(6, "thickness");
      o.color = r.color(7);
      o.contrast = r.contrast(10);
      w.obstacles.push_back(o);
    } else if (kw == "box") {
      r.arity(9, 10, "box CX CY SX SY ROT_DEG HEIGHT R G B [CONTRAST]");
      Obstacle o;
      o.kind = ObstacleKind::Box;
      o.p = {r.num(1, "cx"), r.num(2, "cy"), r.positive(3, "sx"), r.positive(4, "sy"),
             r.num(5, "rotation")};
      o.height_in = r.positive(6, "height");
      o.color = r.color(7);
      o.contrast = r.contrast(10);
      w.obstacles.push_back(o);
    } else if (kw == "cylinder") {
      r.arity(7, 8, "cylinder CX CY RADIUS HEIGHT R G B [CONTRAST]");
      Obstacle o;
      o.kind = ObstacleKind::Cylinder;
      o.p = {r.num(1, "cx"), r.num(2, "cy"), r.positive(3, "radius"), 0, 0};
      o.height_in = r.positive(4, "height");
      o.color = r.color(5);
      o.contrast = r.contrast(8);
      w.obstacles.push_back(o);
    } else if (kw == "mover") {
      r.arity(11, 12, "mover cylinder|box SIZE HEIGHT R G B X0 Y0 X1 Y1 SPEED [CONTRAST]");
      MoverDef m;
      if (r.tok[1] != "cylinder" && r.tok[1] != "box")
        r.fail("mover: shape must be 'cylinder' or 'box', not '" + r.tok[1] + "'");
      m.cylinder = r.tok[1] == "cylinder";
      m.size_in = r.positive(2, "size");
      m.height_in = r.positive(3, "height");
      m.color = r.color(4);
      m.a = {r.num(7, "x0"), r.num(8, "y0")};
      m.b = {r.num(9, "x1"), r.num(10, "y1")};
      m.speed_in = r.num(11, "speed");
      if (m.speed_in < 0) r.fail("mover: speed must be >= 0");
      m.contrast = r.contrast(12);
      w.movers.push_back(m);
    } else {
      r.fail("unknown item '" + kw +
             "' (expected name, texture_seed, floor, background, light, start, wall, box, "
             "cylinder or mover)");
    }
  }
  if (!have_start) throw InputError(where + ": no 'start X Y HEADING_DEG' line");
  if (w.name.empty()) w.name = fs::path(where).stem().string();
  for (auto &o : w.obstacles) o.finalize();
  return w;
}

std::string format_arena(const World &w) {
  std::string s = "name " + w.name + "\n";
  s += "texture_seed " + std::to_string(w.texture_seed) + "\n";
  s += "floor " + fmt(w.floor_color) + " " + fmt(w.floor_contrast) + "\n";
  s += "background " + fmt(w.background) + "\n";
  s += "light " + fmt(w.light.ambient) + " " + fmt(w.light.diffuse) + " " +
       fmt(w.light.azimuth_deg) + " " + fmt(w.light.elevation_deg) + "\n";
  s += "start " + fmt(w.start.x_in) + " " + fmt(w.start.y_in) + " " + fmt(w.start.heading_deg) + "\n";
  for (const auto &o : w.obstacles) {
    if (o.mover >= 0) continue;
    const auto &p = o.p;
    switch (o.kind) {
      case ObstacleKind::Wall:
        s += "wall " + fmt(p[0]) + " " + fmt(p[1]) + " " + fmt(p[2]) + " " + fmt(p[3]) + " " +
             fmt(o.height_in) + " " + fmt(p[4]);
        break;
      case ObstacleKind::Box:
        s += "box " + fmt(p[0]) + " " + fmt(p[1]) + " " + fmt(p[2]) + " " + fmt(p[3]) + " " +
             fmt(p[4]) + " " + fmt(o.height_in);
        break;
      case ObstacleKind::Cylinder:
        s += "cylinder " + fmt(p[0]) + " " + fmt(p[1]) + " " + fmt(p[2]) + " " + fmt(o.height_in);
        break;
    }
    s += " " + fmt(o.color) + " " + fmt(o.contrast) + "\n";
  }
  for (const auto &m : w.movers)
    s += std::string("mover ") + (m.cylinder ? "cylinder " : "box ") + fmt(m.size_in) + " " +
         fmt(m.height_in) + " " + fmt(m.color) + " " + fmt(m.a.x) + " " + fmt(m.a.y) + " " +
         fmt(m.b.x) + " " + fmt(m.b.y) + " " + fmt(m.speed_in) + " " + fmt(m.contrast) + "\n";
  return s;
}

std::vector<std::string> arena_search_dirs() {
  std::vector<std::string> dirs;
  if (const char *e = std::getenv("BVB_ARENA_DIR"); e && *e) dirs.push_back(e);
#ifdef BVB_SOURCE_DIR
  dirs.push_back(std::string(BVB_SOURCE_DIR) + "/frames/arenas");
#endif
  dirs.push_back("frames/arenas");
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec)
    for (fs::path d = exe.parent_path(); !d.empty(); d = d.parent_path()) {
      dirs.push_back((d / "frames" / "arenas").string());
      if (d == d.root_path()) break;
    }
  return dirs;
}

std::vector<std::string> list_arenas() {
  for (const auto &d : arena_search_dirs()) {
    std::error_code ec;
    std::vector<std::string> names;
    for (fs::directory_iterator it(d, ec), end; !ec && it != end; it.increment(ec))
      if (it->path().extension() == ".txt") names.push_back(it->path().stem().string());
    if (!names.empty()) {
      std::sort(names.begin(), names.end());
      return names;
    }
  }
  return {};
}

World load_arena(const std::string &name_or_path) {
  if (name_or_path.find('/') != std::string::npos ||
      (name_or_path.size() > 4 && name_or_path.compare(name_or_path.size() - 4, 4, ".txt") == 0)) {
    auto bytes = read_file(name_or_path);
    return parse_arena(std::string(bytes.begin(), bytes.end()), name_or_path);
  }
  if (name_or_path.empty() ||
      name_or_path.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                     "0123456789_-") != std::string::npos)
    throw InputError("arena '" + name_or_path + "': not a valid arena name");
  for (const auto &d : arena_search_dirs()) {
    const std::string p = d + "/" + name_or_path + ".txt";
    std::error_code ec;
    if (fs::is_regular_file(p, ec)) {
      auto bytes = read_file(p);
      World w = parse_arena(std::string(bytes.begin(), bytes.end()), p);
      return w;
    }
  }
  std::string known;
  for (const auto &n : list_arenas()) known += (known.empty() ? "" : ", ") + n;
  throw InputError("arena '" + name_or_path + "' not found (known: " +
                   (known.empty() ? "none; set BVB_ARENA_DIR to frames/arenas" : known) + ")");
}

World world_at_frame(const World &w, int frame) {
  World out = w;
  for (size_t i = 0; i < w.movers.size(); ++i) {
    const MoverDef &m = w.movers[i];
    const Vec2 c = m.position(frame);
    Obstacle o;
    if (m.cylinder) {
      o.kind = ObstacleKind::Cylinder;
      o.p = {c.x, c.y, m.size_in, 0, 0};
    } else {
      o.kind = ObstacleKind::Box;
      o.p = {c.x, c.y, m.size_in, m.size_in, 0};
    }
    o.height_in = m.height_in;
    o.color = m.color;
    o.contrast = m.contrast;
    o.mover = int(i);
    o.finalize();
    out.obstacles.push_back(o);
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
// Collision and clearance

namespace {

double seg_dist2(Vec2 p, Vec2 a, Vec2 b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double l2 = dx * dx + dy * dy;
  double t = l2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / l2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  const double ex = a.x + t * dx - p.x, ey = a.y + t * dy - p.y;
  return ex * ex + ey * ey;
}

}  // namespace

bool collides(const World &w, const Pose &pose, double radius_in) {
  const Vec2 c{pose.x_in, pose.y_in};
  for (const auto &o : w.obstacles) {
    if (o.kind == ObstacleKind::Cylinder) {
      if (std::hypot(c.x - o.centre.x, c.y - o.centre.y) < radius_in + o.radius) return true;
      continue;
    }
    bool inside = true;
    double d2 = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 4; ++k) {
      const Vec2 a = o.corners[size_t(k)], b = o.corners[size_t((k + 1) & 3)];
      if ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x) < 0) inside = false;
      d2 = std::min(d2, seg_dist2(c, a, b));
    }
    if (inside || d2 < radius_in * radius_in) return true;
  }
  return false;
}

double corridor_clearance(const World &w, const Pose &pose, double radius_in) {
  const double h = deg2rad(pose.heading_deg);
  const double fx = std::cos(h), fy = std::sin(h);  // forward; left is (-fy, fx)
  const double R = radius_in;
  double best = std::numeric_limits<double>::infinity();
  for (const auto &o : w.obstacles) {
    if (o.kind == ObstacleKind::Cylinder) {
      const double dx = o.centre.x - pose.x_in, dy = o.centre.y - pose.y_in;
      const double f = dx * fx + dy * fy, l = -dx * fy + dy * fx, al = std::fabs(l);
      double lo, hi;  // forward extent of the disc inside the strip |lateral| <= R
      if (al <= R) {
        lo = f - o.radius;
        hi = f + o.radius;
      } else if (al - R < o.radius) {
        const double e = std::sqrt(o.radius * o.radius - (al - R) * (al - R));
        lo = f - e;
        hi = f + e;
      } else {
        continue;
      }
      if (hi < 0) continue;
      best = std::min(best, std::max(lo, 0.0));
      continue;
    }
    // Clip the footprint, in robot coordinates, to the strip ahead (Sutherland-Hodgman).
    std::vector<Vec2> poly;
    for (const auto &p : o.corners) {
      const double dx = p.x - pose.x_in, dy = p.y - pose.y_in;
      poly.push_back({dx * fx + dy * fy, -dx * fy + dy * fx});
    }
    auto clip = [&](auto inside_value) {  // keeps value(p) >= 0
      std::vector<Vec2> out;
      for (size_t i = 0; i < poly.size(); ++i) {
        const Vec2 a = poly[i], b = poly[(i + 1) % poly.size()];
        const double va = inside_value(a), vb = inside_value(b);
        if (va >= 0) out.push_back(a);
        if ((va >= 0) != (vb >= 0)) {
          const double t = va / (va - vb);
          out.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
        }
      }
      poly.swap(out);
    };
    clip([&](Vec2 p) { return R - p.y; });
    clip([&](Vec2 p) { return p.y + R; });
    clip([&](Vec2 p) { return p.x; });
    for (const auto &p : poly) best = std::min(best, p.x);
  }
  return best - R;
}

}  // namespace bvb
