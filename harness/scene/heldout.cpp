#include "heldout.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "io.h"
#include "rng.h"

namespace bvb {

namespace {

// Stream tags: each kind of scene draws from streams of its own.
constexpr uint64_t kTagAvoid = 0x61766f6964ull, kTagOdometry = 0x6f646f6dull, kTagPolygon = 0x706f6c79ull;

struct Draw {
  SceneRng rng;
  explicit Draw(uint64_t key) : rng(key) {}
  double in(double lo, double hi) { return lo + (hi - lo) * rng.uniform(); }
  int whole(int lo, int hi) { return lo + int(rng.next() % uint64_t(hi - lo + 1)); }  // lo..hi
  bool chance(double p) { return rng.uniform() < p; }
};

double round_to(double v, double step) { return std::round(v / step) * step; }

std::string num(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.10g", v);
  return b;
}

// The bundled arenas' obstacle colours (frames/arenas/): each lit luma stays some 40 levels or
// more from the floor's, which ground segmentation needs (world.h).
struct Paint {
  Rgb color;
  double contrast;
};
const Paint kPaints[] = {{{170, 35, 30}, 0.2}, {{40, 60, 180}, 0.2}, {{235, 235, 230}, 0.12}, {{50, 50, 60}, 0.25}};
const Paint kWallPaint{{225, 225, 215}, 0.08};

// Floor, background and light near the bundled arenas' (a mid-brown floor, luma ~120).
void draw_surroundings(Draw &d, World &w) {
  w.floor_color = {float(round_to(d.in(130, 150), 1)), float(round_to(d.in(105, 125), 1)),
                   float(round_to(d.in(80, 100), 1))};
  w.floor_contrast = round_to(d.in(0.2, 0.3), 0.01);
  w.background = {90, 95, 110};
  w.light.ambient = round_to(d.in(0.7, 0.8), 0.01);
  w.light.diffuse = round_to(d.in(0.25, 0.35), 0.01);
  w.light.azimuth_deg = round_to(d.in(0, 360), 1);
  w.light.elevation_deg = round_to(d.in(50, 65), 1);
  // The texture seeds an arena file may hold: 0..kMaxTextureSeed.
  w.texture_seed = d.rng.next() % uint64_t(kMaxTextureSeed + 1);
}

Obstacle wall(double x0, double y0, double x1, double y1) {
  Obstacle o;
  o.kind = ObstacleKind::Wall;
  o.p = {x0, y0, x1, y1, 1};
  o.height_in = 14;
  o.color = kWallPaint.color;
  o.contrast = kWallPaint.contrast;
  return o;
}

void add_room(World &w, double width, double height) {
  w.obstacles.push_back(wall(0, 0, width, 0));
  w.obstacles.push_back(wall(width, 0, width, height));
  w.obstacles.push_back(wall(width, height, 0, height));
  w.obstacles.push_back(wall(0, height, 0, 0));
}

// A box or a cylinder at (cx, cy); its bounding radius in *reach.
Obstacle draw_obstacle(Draw &d, double cx, double cy, double *reach) {
  Obstacle o;
  const Paint &paint = kPaints[d.whole(0, 3)];
  o.color = paint.color;
  o.contrast = paint.contrast;
  if (d.chance(0.6)) {
    o.kind = ObstacleKind::Box;
    const double sx = round_to(d.in(6, 20), 0.5), sy = round_to(d.in(6, 20), 0.5);
    o.p = {cx, cy, sx, sy, round_to(d.in(0, 90), 1)};
    o.height_in = round_to(d.in(3, 12), 0.5);
    *reach = 0.5 * std::hypot(sx, sy);
  } else {
    o.kind = ObstacleKind::Cylinder;
    const double r = round_to(d.in(2.5, 6), 0.25);
    o.p = {cx, cy, r, 0, 0};
    o.height_in = round_to(d.in(6, 14), 0.5);
    *reach = r;
  }
  return o;
}

double seg_dist(Vec2 p, Vec2 a, Vec2 b) {
  const double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
  const double t = l2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / l2, 0.0, 1.0) : 0;
  return std::hypot(a.x + t * dx - p.x, a.y + t * dy - p.y);
}

struct Placed {
  Vec2 c;
  double reach;
};

// Scatters up to `count` obstacles over the room [margin, size - margin], each at least `gap`
// from the others (bounding circles) and accepted by `ok` (centre, reach).
template <class Ok>
void scatter(Draw &d, World &w, std::vector<Placed> &placed, int count, double width, double height, double gap,
             Ok ok) {
  for (int k = 0, tries = 0; k < count && tries < 400; ++tries) {
    const double cx = round_to(d.in(4, width - 4), 0.5), cy = round_to(d.in(4, height - 4), 0.5);
    double reach = 0;
    Obstacle o = draw_obstacle(d, cx, cy, &reach);
    bool fits = cx - reach > 1 && cy - reach > 1 && cx + reach < width - 1 && cy + reach < height - 1 &&
                ok(Vec2{cx, cy}, reach);
    for (const Placed &p : placed)
      if (std::hypot(p.c.x - cx, p.c.y - cy) < p.reach + reach + gap) fits = false;
    if (!fits) continue;
    placed.push_back({{cx, cy}, reach});
    w.obstacles.push_back(o);
    ++k;
  }
}

void finish(HeldoutScene &s, const SceneSpec &base, const Pose &start, int frames, const std::string &path) {
  s.arena.name = s.name;
  s.arena.start = start;
  finalize_world(s.arena);
  s.spec = base;
  s.spec.arena = s.name;
  s.spec.path = path;
  s.spec.frames = frames;
  s.spec.has_start = true;
  s.spec.start = start;
  s.spec.has_texture_seed = true;
  s.spec.texture_seed = s.arena.texture_seed;
  s.spec.mover = "none";
  s.spec.write_uyvy = s.spec.write_flow = false;
}

}  // namespace

double HeldoutPolygon::length_in() const {
  double s = 0;
  for (double l : legs_in) s += l;
  return s;
}

std::string HeldoutPolygon::script() const {
  std::string s;
  for (size_t i = 0; i < legs_in.size(); ++i) {
    if (i) s += "+";
    s += "F" + num(legs_in[i]) + "+" + (turns_deg[i] < 0 ? "R" : "L") + num(std::fabs(turns_deg[i]));
  }
  return s;
}

HeldoutPolygon heldout_polygon(uint64_t seed) {
  Draw d(hash_key(seed, kTagPolygon));
  const int n = d.whole(3, 8);
  const size_t count = size_t(n);
  const double sign = d.chance(0.5) ? 1 : -1;
  for (int attempt = 0;; ++attempt) {
    // Exterior angles: random weights scaled to 360 degrees, each within 15..165 (convex, and
    // no leg nearly parallel to the next, which would make the closing legs ill-conditioned).
    std::vector<double> w(count), t(count);
    double sum = 0;
    for (double &v : w) sum += (v = d.in(0.5, 1.5));
    bool ok = true;
    for (int i = 0; i < n; ++i) {
      t[size_t(i)] = round_to(360.0 * w[size_t(i)] / sum, 0.01);
      ok = ok && t[size_t(i)] >= 15 && t[size_t(i)] <= 165;
    }
    // The last angle takes the rounding, so that the turns add up to 360 exactly.
    double rest = 360;
    for (int i = 0; i + 1 < n; ++i) rest -= t[size_t(i)];
    t[size_t(n - 1)] = round_to(rest, 0.01);
    ok = ok && t[size_t(n - 1)] >= 15 && t[size_t(n - 1)] <= 165;
    // Legs 2..n-1 at random; legs 0 and 1 close the polygon: L0 u0 + L1 u1 = -sum_{i>=2} Li ui.
    std::vector<double> L(count), hx(count), hy(count);
    double h = 0;
    for (int i = 0; i < n; ++i) {
      hx[size_t(i)] = std::cos(deg2rad(h));
      hy[size_t(i)] = std::sin(deg2rad(h));
      h += t[size_t(i)];
    }
    double rx = 0, ry = 0;
    for (int i = 2; i < n; ++i) {
      L[size_t(i)] = round_to(d.in(12, 36), 0.01);
      rx -= L[size_t(i)] * hx[size_t(i)];
      ry -= L[size_t(i)] * hy[size_t(i)];
    }
    const double det = hx[0] * hy[1] - hy[0] * hx[1];
    L[0] = round_to((rx * hy[1] - ry * hx[1]) / det, 0.01);
    L[1] = round_to((hx[0] * ry - hy[0] * rx) / det, 0.01);
    ok = ok && L[0] >= 12 && L[0] <= 36 && L[1] >= 12 && L[1] <= 36;
    if (ok || attempt > 100000) {
      if (!ok) throw InputError("held-out polygon: no closed polygon found for seed " + std::to_string(seed));
      HeldoutPolygon p;
      p.legs_in = L;
      for (double v : t) p.turns_deg.push_back(sign * v);
      return p;
    }
  }
}

std::string HeldoutScene::describe() const {
  int boxes = 0, cylinders = 0, walls = 0;
  double wx = 0, wy = 0;
  for (const Obstacle &o : arena.obstacles) {
    if (o.kind == ObstacleKind::Box) ++boxes;
    if (o.kind == ObstacleKind::Cylinder) ++cylinders;
    if (o.kind == ObstacleKind::Wall) {
      ++walls;
      wx = std::max({wx, o.p[0], o.p[2]});
      wy = std::max({wy, o.p[1], o.p[3]});
    }
  }
  char b[320];
  std::snprintf(b, sizeof b, "room %.0fx%.0f in, %d boxes, %d cylinders%s, texture_seed %llu, start %.1f:%.1f:%.0f",
                wx, wy, boxes, cylinders, walls > 4 ? ", a partition" : "",
                static_cast<unsigned long long>(arena.texture_seed), spec.start.x_in, spec.start.y_in,
                spec.start.heading_deg);
  std::string s = b;
  if (!polygon.legs_in.empty()) {
    std::snprintf(b, sizeof b, ", %zu sides, %.1f in", polygon.legs_in.size(), polygon.length_in());
    s += b;
  }
  return s;
}

HeldoutScene heldout_avoid_scene(uint64_t seed, int index, int frames, const SceneSpec &base) {
  Draw d(hash_key(seed, kTagAvoid, uint64_t(index)));
  HeldoutScene s;
  s.name = "heldout-avoid-" + std::to_string(index);
  draw_surroundings(d, s.arena);
  const double width = round_to(d.in(84, 168), 1), height = round_to(d.in(84, 168), 1);
  add_room(s.arena, width, height);
  // Sometimes a partition from one wall, leaving a passage of at least 30 in: corridors and
  // dead ends like the bundled corridor arena's.
  std::vector<std::pair<Vec2, Vec2>> partitions;
  if (d.chance(0.4)) {
    const bool vertical = d.chance(0.5);
    const double span = vertical ? height : width, across = vertical ? width : height;
    const double at = round_to(d.in(0.35, 0.65) * across, 1), len = round_to(d.in(0.3 * span, span - 30), 1);
    const bool from_low = d.chance(0.5);
    const double a = from_low ? 0 : span, b = from_low ? len : span - len;
    const Vec2 p0 = vertical ? Vec2{at, a} : Vec2{a, at}, p1 = vertical ? Vec2{at, b} : Vec2{b, at};
    s.arena.obstacles.push_back(wall(p0.x, p0.y, p1.x, p1.y));
    partitions.push_back({p0, p1});
  }
  // Obstacles at least 8 in apart (the robot's 6 in disc passes between any two) and as far
  // from a partition.
  std::vector<Placed> placed;
  scatter(d, s.arena, placed, d.whole(3, 9), width, height, 8, [&](Vec2 c, double reach) {
    for (const auto &pw : partitions)
      if (seg_dist(c, pw.first, pw.second) < reach + 8) return false;
    return true;
  });
  // A start with room to move: 3 in of air around the robot's disc.
  finalize_world(s.arena);
  Pose start;
  for (int tries = 0;; ++tries) {
    start = {round_to(d.in(8, width - 8), 0.1), round_to(d.in(8, height - 8), 0.1), round_to(d.in(-180, 180), 1)};
    if (!collides(s.arena, start, kRobotRadiusIn + 3)) break;
    if (tries > 10000) throw InputError("held-out arena " + s.name + ": no free start");
  }
  finish(s, base, start, frames, "avoid");
  return s;
}

HeldoutScene heldout_odometry_scene(uint64_t seed, int index, const SceneSpec &base) {
  Draw d(hash_key(seed, kTagOdometry, uint64_t(index)));
  HeldoutScene s;
  s.name = "heldout-odometry-" + std::to_string(index);
  s.polygon = heldout_polygon(hash_key(seed, kTagOdometry, uint64_t(index), 1));
  draw_surroundings(d, s.arena);
  // The polygon's corners from a start at the origin with a random heading, through the same
  // steps the scene will take.
  const double heading = round_to(d.in(-180, 180), 1);
  std::vector<Vec2> corners;
  Pose p{0, 0, heading};
  for (size_t i = 0; i < s.polygon.legs_in.size(); ++i) {
    corners.push_back({p.x_in, p.y_in});
    p = step_pose(p, s.polygon.legs_in[i], 0);
    p.heading_deg += s.polygon.turns_deg[i];
  }
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  for (const Vec2 &c : corners) {
    x0 = std::min(x0, c.x), y0 = std::min(y0, c.y);
    x1 = std::max(x1, c.x), y1 = std::max(y1, c.y);
  }
  // Walls 12 to 36 in beyond the path on each side.
  const double ml = d.in(12, 36), mb = d.in(12, 36), mr = d.in(12, 36), mt = d.in(12, 36);
  const double ox = round_to(ml - x0, 0.1), oy = round_to(mb - y0, 0.1);
  const double width = round_to(ox + x1 + mr, 1), height = round_to(oy + y1 + mt, 1);
  add_room(s.arena, width, height);
  for (Vec2 &c : corners) c = {c.x + ox, c.y + oy};
  // Obstacles inside and around the polygon, their bounding circles 7 in or more from the path
  // (the robot's 3 in radius and 4 in of air), so the scripted path never touches one.
  std::vector<Placed> placed;
  scatter(d, s.arena, placed, d.whole(3, 8), width, height, 4, [&](Vec2 c, double reach) {
    for (size_t i = 0; i < corners.size(); ++i)
      if (seg_dist(c, corners[i], corners[(i + 1) % corners.size()]) < reach + kRobotRadiusIn + 4) return false;
    return true;
  });
  finish(s, base, Pose{ox, oy, heading}, 0, s.polygon.script());
  return s;
}

}  // namespace bvb
