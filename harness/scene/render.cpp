#include "render.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rng.h"

namespace bvb {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kTile = 8;           // culling tiles of kTile x kTile pixels
constexpr double kTMin = 1e-9;

constexpr int kFaceTop = 4, kFaceCylSide = 5;

// An obstacle laid out for ray tests, and what is needed to shade it.
struct Prep {
  bool cyl = false;
  double nx[4], ny[4], c[4];          // inside the footprint: nx x + ny y <= c
  double vx[4], vy[4], ex[4], ey[4];  // corner k and the unit direction of edge k
  double cx = 0, cy = 0, r = 0, h = 0;  // centre (of every shape: textures are tied to it)
  float col[3];
  float contrast;
  float shade[5];                     // side faces 0..3, top 4
  double tu[6], tv[6];                // texture offsets per face
};

struct Hit {
  double t = kInf;
  int obj = kSurfaceNone;  // index, kSurfaceFloor or kSurfaceNone
  int face = 0;
};

class Tracer {
 public:
  Tracer(const World &w, const Pose &pose, const Camera &cam)
      : world_(w), cam_(cam), view_(cam, pose) {
    const Lighting &L = w.light;
    const double el = deg2rad(L.elevation_deg), az = deg2rad(L.azimuth_deg);
    lx_ = std::cos(el) * std::cos(az);
    ly_ = std::cos(el) * std::sin(az);
    floor_shade_ = float(L.ambient + L.diffuse * std::sin(el));
    prep_.reserve(w.obstacles.size());
    for (size_t i = 0; i < w.obstacles.size(); ++i) prep_.push_back(prepare(w.obstacles[i], i));
    build_tiles();
  }

  const CameraView &view() const { return view_; }
  size_t count() const { return prep_.size(); }

  // Candidate obstacles for rays within a pixel of pixel (ix, iy); nullptr means all of them.
  const std::vector<int> *candidates(int ix, int iy) const {
    if (ix < 0 || iy < 0 || ix >= cam_.width || iy >= cam_.height) return nullptr;
    return &tiles_[size_t(iy / kTile) * tiles_x_ + size_t(ix / kTile)];
  }

  Hit trace(const Vec3 &d, const std::vector<int> *cand) const {
    Hit best;
    const Vec3 &C = view_.centre;
    if (d.z < 0) {
      best.t = -C.z / d.z;
      best.obj = kSurfaceFloor;
    }
    if (cand) {
      for (int i : *cand) intersect(i, d, best);
    } else {
      for (size_t i = 0; i < prep_.size(); ++i) intersect(int(i), d, best);
    }
    return best;
  }

  // Linear RGB of a hit; pixel_rad is the angular size of the pixel (or sub-pixel) it stands
  // for, which sets the texture filter width.
  void shade(const Vec3 &d, const Hit &hit, double pixel_rad, float out[3]) const {
    if (hit.obj == kSurfaceNone) {
      out[0] = world_.background.r;
      out[1] = world_.background.g;
      out[2] = world_.background.b;
      return;
    }
    const Vec3 &C = view_.centre;
    const Vec3 P = C + hit.t * d;
    const double dlen = std::sqrt(dot(d, d));
    const Texture &T = *world_.texture;
    auto lod_for = [&](double cos_inc) {
      const double foot = hit.t * dlen * pixel_rad / std::sqrt(std::max(cos_inc, 0.05));
      return std::log2(std::max(foot, 1e-9) / T.texel_in);
    };
    if (hit.obj == kSurfaceFloor) {
      const float tex = T.sample(P.x, P.y, lod_for(-d.z / dlen));
      const float k = (1.f + float(world_.floor_contrast) * tex) * floor_shade_;
      out[0] = world_.floor_color.r * k;
      out[1] = world_.floor_color.g * k;
      out[2] = world_.floor_color.b * k;
      return;
    }
    const Prep &p = prep_[size_t(hit.obj)];
    float tex, light;
    if (hit.face == kFaceTop) {
      tex = T.sample(P.x - p.cx + p.tu[4], P.y - p.cy + p.tv[4], lod_for(std::fabs(d.z) / dlen));
      light = p.shade[4];
    } else if (hit.face == kFaceCylSide) {
      const double nx = (P.x - p.cx) / p.r, ny = (P.y - p.cy) / p.r;
      const double cos_inc = std::fabs(nx * d.x + ny * d.y) / dlen, lod = lod_for(cos_inc);
      // Two planar projections blended by the normal: no seam around the cylinder.
      const float wx = float(nx * nx), wy = float(ny * ny);
      tex = wx * T.sample(P.y - p.cy + p.tu[5], P.z + p.tv[5], lod) +
            wy * T.sample(P.x - p.cx + p.tu[5], P.z + p.tv[5], lod);
      const Lighting &L = world_.light;
      light = float(L.ambient + L.diffuse * std::max(0.0, nx * lx_ + ny * ly_));
    } else {
      const int k = hit.face;
      const double u = (P.x - p.vx[k]) * p.ex[k] + (P.y - p.vy[k]) * p.ey[k];
      const double cos_inc = std::fabs(p.nx[k] * d.x + p.ny[k] * d.y) / dlen;
      tex = T.sample(u + p.tu[k], P.z + p.tv[k], lod_for(cos_inc));
      light = p.shade[k];
    }
    const float m = (1.f + p.contrast * tex) * light;
    out[0] = p.col[0] * m;
    out[1] = p.col[1] * m;
    out[2] = p.col[2] * m;
  }

 private:
  Prep prepare(const Obstacle &o, size_t index) const {
    Prep p;
    p.h = o.height_in;
    p.col[0] = o.color.r;
    p.col[1] = o.color.g;
    p.col[2] = o.color.b;
    p.contrast = float(o.contrast);
    const Lighting &L = world_.light;
    const double el = deg2rad(L.elevation_deg);
    p.shade[4] = float(L.ambient + L.diffuse * std::sin(el));
    // Texture offsets: each face shows a different part of the texture. Coordinates are taken
    // relative to the obstacle (corner or centre), so a mover's texture travels with it.
    p.cx = o.centre.x;
    p.cy = o.centre.y;
    for (int f = 0; f < 6; ++f) {
      const uint64_t key = hash_key(world_.texture_seed, o.mover >= 0 ? 1000 + o.mover : index, f);
      p.tu[f] = double(key & 0xffff) * (128.0 / 65536.0);
      p.tv[f] = double((key >> 16) & 0xffff) * (128.0 / 65536.0);
    }
    if (o.kind == ObstacleKind::Cylinder) {
      p.cyl = true;
      p.r = o.radius;
      return p;
    }
    for (int k = 0; k < 4; ++k) {
      const Vec2 a = o.corners[size_t(k)], b = o.corners[size_t((k + 1) & 3)];
      const double len = std::hypot(b.x - a.x, b.y - a.y);
      p.vx[k] = a.x;
      p.vy[k] = a.y;
      p.ex[k] = (b.x - a.x) / len;
      p.ey[k] = (b.y - a.y) / len;
      p.nx[k] = p.ey[k];
      p.ny[k] = -p.ex[k];
      p.c[k] = p.nx[k] * a.x + p.ny[k] * a.y;
      p.shade[k] = float(L.ambient + L.diffuse * std::max(0.0, p.nx[k] * lx_ + p.ny[k] * ly_));
    }
    return p;
  }

  void intersect(int i, const Vec3 &d, Hit &best) const {
    const Prep &p = prep_[size_t(i)];
    const Vec3 &C = view_.centre;
    if (p.cyl) {
      const double a = d.x * d.x + d.y * d.y;
      const double ox = C.x - p.cx, oy = C.y - p.cy;
      if (a < 1e-18) {  // a vertical ray: only the top cap
        if (d.z < 0 && C.z > p.h && ox * ox + oy * oy <= p.r * p.r) {
          const double th = (p.h - C.z) / d.z;
          if (th < best.t) best = {th, i, kFaceTop};
        }
        return;
      }
      const double b = ox * d.x + oy * d.y, cc = ox * ox + oy * oy - p.r * p.r;
      const double disc = b * b - a * cc;
      if (disc < 0) return;
      const double s = std::sqrt(disc), tin = (-b - s) / a, tout = (-b + s) / a;
      if (tout <= kTMin || tin >= best.t) return;
      if (tin <= kTMin) {  // the camera is inside the cylinder's footprint
        if (C.z <= p.h) {
          best = {kTMin, i, kFaceCylSide};
        } else if (d.z < 0) {
          const double th = (p.h - C.z) / d.z;
          if (th <= tout && th < best.t) best = {th, i, kFaceTop};
        }
        return;
      }
      const double zin = C.z + tin * d.z;
      if (zin >= 0 && zin <= p.h) {
        best = {tin, i, kFaceCylSide};
      } else if (zin > p.h && d.z < 0) {
        const double th = (p.h - C.z) / d.z;
        if (th >= tin && th <= tout && th < best.t) best = {th, i, kFaceTop};
      }
      return;
    }
    double t0 = kTMin, t1 = best.t;
    int face = -1;
    if (d.z < 0) {
      const double th = (p.h - C.z) / d.z;
      if (th > t0) {
        t0 = th;
        face = kFaceTop;
      }
    } else if (C.z > p.h) {
      return;
    } else if (d.z > 0) {
      t1 = std::min(t1, (p.h - C.z) / d.z);
    }
    for (int k = 0; k < 4; ++k) {
      const double den = p.nx[k] * d.x + p.ny[k] * d.y;
      const double num = p.c[k] - (p.nx[k] * C.x + p.ny[k] * C.y);
      if (den < 0) {
        const double t = num / den;
        if (t > t0) {
          t0 = t;
          face = k;
        }
      } else if (den > 0) {
        t1 = std::min(t1, num / den);
      } else if (num < 0) {
        return;
      }
      if (t0 > t1) return;
    }
    if (t0 <= t1 && t0 < best.t) best = {t0, i, face < 0 ? kFaceTop : face};
  }

  // Screen bounding boxes of every obstacle -> per-tile candidate lists.
  void build_tiles() {
    tiles_x_ = (cam_.width + kTile - 1) / kTile;
    const int tiles_y = (cam_.height + kTile - 1) / kTile;
    tiles_.assign(size_t(tiles_x_) * tiles_y, {});
    const double near = 1e-3;
    for (size_t i = 0; i < prep_.size(); ++i) {
      const Prep &p = prep_[i];
      Vec3 pts[8];
      int n = 0;
      Vec2 fp[4];
      if (p.cyl) {
        fp[0] = {p.cx - p.r, p.cy - p.r};
        fp[1] = {p.cx + p.r, p.cy - p.r};
        fp[2] = {p.cx + p.r, p.cy + p.r};
        fp[3] = {p.cx - p.r, p.cy + p.r};
      } else {
        for (int k = 0; k < 4; ++k) fp[k] = {p.vx[k], p.vy[k]};
      }
      for (int k = 0; k < 4; ++k) {
        pts[n++] = view_.to_camera({fp[k].x, fp[k].y, 0});
        pts[n++] = view_.to_camera({fp[k].x, fp[k].y, p.h});
      }
      double x0 = kInf, x1 = -kInf, y0 = kInf, y1 = -kInf;
      auto add = [&](const Vec3 &c) {
        const double x = cam_.cx + cam_.fx * c.x / c.z, y = cam_.cy + cam_.fy * c.y / c.z;
        x0 = std::min(x0, x);
        x1 = std::max(x1, x);
        y0 = std::min(y0, y);
        y1 = std::max(y1, y);
      };
      // The hull clipped to z >= near: its corners in front plus every edge's crossing.
      for (int a = 0; a < n; ++a) {
        if (pts[a].z >= near) add(pts[a]);
        for (int b = a + 1; b < n; ++b) {
          const Vec3 &A = pts[a], &B = pts[b];
          if ((A.z >= near) != (B.z >= near)) {
            const double t = (near - A.z) / (B.z - A.z);
            add(A + t * (B - A));
          }
        }
      }
      if (!(x0 <= x1)) continue;  // entirely behind the camera
      const double m = 2.0;
      const int tx0 = int(std::clamp(std::floor((x0 - m) / kTile), 0.0, double(tiles_x_ - 1)));
      const int tx1 = int(std::clamp(std::floor((x1 + m) / kTile), -1.0, double(tiles_x_ - 1)));
      const int ty0 = int(std::clamp(std::floor((y0 - m) / kTile), 0.0, double(tiles_y - 1)));
      const int ty1 = int(std::clamp(std::floor((y1 + m) / kTile), -1.0, double(tiles_y - 1)));
      if (x1 + m < 0 || y1 + m < 0 || x0 - m > cam_.width || y0 - m > cam_.height) continue;
      for (int ty = ty0; ty <= ty1; ++ty)
        for (int tx = tx0; tx <= tx1; ++tx) tiles_[size_t(ty) * tiles_x_ + tx].push_back(int(i));
    }
  }

  const World &world_;
  Camera cam_;
  CameraView view_;
  double lx_, ly_;
  float floor_shade_;
  std::vector<Prep> prep_;
  int tiles_x_ = 0;
  std::vector<std::vector<int>> tiles_;
};

inline uint8_t quantize(double v) {
  const double r = std::floor(v + 0.5);
  return uint8_t(r < 0 ? 0 : r > 255 ? 255 : r);
}

}  // namespace

void rgb_to_yuv(int r, int g, int b, int &y, int &u, int &v) {
  y = ((66 * r + 129 * g + 25 * b + 128) >> 8) + 16;
  u = ((-38 * r - 74 * g + 112 * b + 128) >> 8) + 128;
  v = ((112 * r - 94 * g - 18 * b + 128) >> 8) + 128;
}

Image rgb_to_grey(const Image &rgb) {
  Image g(rgb.width, rgb.height, 1);
  const size_t n = size_t(rgb.width) * rgb.height;
  for (size_t i = 0; i < n; ++i) {
    int y, u, v;
    rgb_to_yuv(rgb.data[3 * i], rgb.data[3 * i + 1], rgb.data[3 * i + 2], y, u, v);
    g.data[i] = uint8_t(y);
  }
  return g;
}

std::vector<uint8_t> rgb_to_uyvy(const Image &rgb) {
  std::vector<uint8_t> out(size_t(rgb.width) * rgb.height * 2);
  const size_t pairs = size_t(rgb.width / 2) * rgb.height;
  for (size_t k = 0; k < pairs; ++k) {
    const uint8_t *p = &rgb.data[6 * k];
    int y0, u0, v0, y1, u1, v1;
    rgb_to_yuv(p[0], p[1], p[2], y0, u0, v0);
    rgb_to_yuv(p[3], p[4], p[5], y1, u1, v1);
    out[4 * k + 0] = uint8_t((u0 + u1 + 1) >> 1);
    out[4 * k + 1] = uint8_t(y0);
    out[4 * k + 2] = uint8_t((v0 + v1 + 1) >> 1);
    out[4 * k + 3] = uint8_t(y1);
  }
  return out;
}

RenderResult render(const World &world, const Pose &pose, const Camera &cam,
                    const RenderOptions &opt) {
  const int W = cam.width, H = cam.height;
  const size_t N = size_t(W) * H;
  Tracer tr(world, pose, cam);
  const CameraView &view = tr.view();
  const double pixel_rad = 1.0 / std::sqrt(cam.fx * cam.fy);

  RenderResult res;
  res.depth.assign(N, float(kInf));
  res.surface.assign(N, kSurfaceNone);
  std::vector<float> col(N * 3);
  std::vector<int> key(N);  // surface and face: the edge test compares these

  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const size_t i = size_t(y) * W + x;
      const Vec3 d = view.ray(x, y);
      const Hit h = tr.trace(d, tr.candidates(x, y));
      tr.shade(d, h, pixel_rad, &col[3 * i]);
      res.surface[i] = int16_t(h.obj);
      res.depth[i] = float(h.t);
      key[i] = h.obj * 8 + (h.obj >= 0 ? h.face : 0);
    }

  const int ss = std::max(1, opt.supersample);
  if (ss > 1) {
    std::vector<uint8_t> edge(N, 0);
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        const size_t i = size_t(y) * W + x;
        const int k = key[i];
        if ((x > 0 && key[i - 1] != k) || (x + 1 < W && key[i + 1] != k) ||
            (y > 0 && key[i - W] != k) || (y + 1 < H && key[i + W] != k))
          edge[i] = 1;
      }
    const double sub_rad = pixel_rad / ss;
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        const size_t i = size_t(y) * W + x;
        if (!edge[i]) continue;
        const auto *cand = tr.candidates(x, y);
        float acc[3] = {0, 0, 0};
        for (int sy = 0; sy < ss; ++sy)
          for (int sx = 0; sx < ss; ++sx) {
            const Vec3 d = view.ray(x + (sx + 0.5) / ss - 0.5, y + (sy + 0.5) / ss - 0.5);
            float c[3];
            tr.shade(d, tr.trace(d, cand), sub_rad, c);
            acc[0] += c[0];
            acc[1] += c[1];
            acc[2] += c[2];
          }
        const float inv = 1.f / float(ss * ss);
        for (int c = 0; c < 3; ++c) col[3 * i + c] = acc[c] * inv;
      }
  }

  res.rgb = Image(W, H, 3);
  SceneRng rng(opt.noise_seed);
  const bool noisy = opt.noise_sigma > 0;
  for (size_t i = 0; i < N * 3; ++i) {
    double v = opt.gain * col[i] + opt.offset;
    if (noisy) v += opt.noise_sigma * rng.gaussian();
    res.rgb.data[i] = quantize(v);
  }
  res.grey = rgb_to_grey(res.rgb);
  if (W % 2 == 0) res.uyvy = rgb_to_uyvy(res.rgb);
  return res;
}

ColumnTruth column_truth(const World &world, const Pose &pose, const Camera &cam) {
  const int W = cam.width, H = cam.height;
  Tracer tr(world, pose, cam);
  const CameraView &view = tr.view();
  ColumnTruth out;
  out.distance_in.assign(size_t(W), kInf);
  out.boundary_row.assign(size_t(W), -1);
  auto hit_at = [&](int x, double y) {
    const int iy = int(std::floor(y + 0.5));
    return tr.trace(view.ray(x, y), (iy >= 0 && iy < H) ? tr.candidates(x, iy) : nullptr);
  };
  auto floor_at = [&](int x, double y) { return hit_at(x, y).obj == kSurfaceFloor; };
  for (int x = 0; x < W; ++x) {
    double y_obj = 0, y_floor = 0;  // a non-floor and a floor y bracketing the transition
    bool found = false;
    int r = -1;
    for (int y = H - 1; y >= 0; --y)
      if (!floor_at(x, y)) {
        r = y;
        break;
      }
    if (r == H - 1) {
      // The floor ends below the image: walk down (rays steepen towards the camera's foot).
      for (double step = 1, y = H - 1; y < H - 1 + 1e6; step *= 1.25) {
        const double yn = y + step;
        if (floor_at(x, yn)) {
          y_obj = y;
          y_floor = yn;
          found = true;
          break;
        }
        y = yn;
      }
      out.boundary_row[size_t(x)] = H - 1;
      if (!found) {  // nothing but obstacle down to the vertical: the robot stands against it
        out.distance_in[size_t(x)] = 0;
        continue;
      }
    } else if (r >= 0) {
      y_obj = r;
      y_floor = r + 1;
      found = true;
      out.boundary_row[size_t(x)] = r;
    } else {
      // Floor in every row: walk up until the floor ends (at the latest at the horizon).
      for (double y = 0; y > -1e6; y -= 1) {
        if (!floor_at(x, y - 1)) {
          y_obj = y - 1;
          y_floor = y;
          found = true;
          break;
        }
      }
      out.boundary_row[size_t(x)] = -1;
      if (!found) continue;
    }
    for (int it = 0; it < 60 && y_floor - y_obj > 1e-7; ++it) {
      const double mid = 0.5 * (y_obj + y_floor);
      if (floor_at(x, mid))
        y_floor = mid;
      else
        y_obj = mid;
    }
    if (hit_at(x, y_obj).obj == kSurfaceNone) continue;  // open floor up to the horizon
    const Vec3 d = view.ray(x, y_floor);
    const double t = -view.centre.z / d.z;
    out.distance_in[size_t(x)] = std::hypot(t * d.x, t * d.y);
  }
  return out;
}

FlowField true_flow(const World &wa, const Pose &pa, const RenderResult &ra, const World &wb,
                    const Pose &pb, const RenderResult &rb, const Camera &cam) {
  const int W = cam.width, H = cam.height;
  const CameraView va(cam, pa), vb(cam, pb);
  FlowField f(W, H);
  const float unknown = 1e10f;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const size_t i = size_t(y) * W + x;
      const int s = ra.surface[i];
      const Vec3 d = va.ray(x, y);
      Vec3 pc;
      if (s == kSurfaceNone) {
        pc = {dot(d, vb.xc), dot(d, vb.yc), dot(d, vb.zc)};
      } else {
        Vec3 P = va.centre + double(ra.depth[i]) * d;
        if (s >= 0 && wa.obstacles[size_t(s)].mover >= 0 && size_t(s) < wb.obstacles.size()) {
          P.x += wb.obstacles[size_t(s)].centre.x - wa.obstacles[size_t(s)].centre.x;
          P.y += wb.obstacles[size_t(s)].centre.y - wa.obstacles[size_t(s)].centre.y;
        }
        pc = vb.to_camera(P);
      }
      if (!(pc.z > 1e-6)) {
        f.u[i] = f.v[i] = unknown;
        continue;
      }
      const double xb = cam.cx + cam.fx * pc.x / pc.z, yb = cam.cy + cam.fy * pc.y / pc.z;
      f.u[i] = float(xb - x);
      f.v[i] = float(yb - y);
      if (xb >= 0 && yb >= 0 && xb <= W - 1 && yb <= H - 1) {
        const int x0 = std::min(int(xb), W - 2 < 0 ? 0 : W - 2),
                  y0 = std::min(int(yb), H - 2 < 0 ? 0 : H - 2);
        float far = 0;
        for (int dy = 0; dy < 2; ++dy)
          for (int dx = 0; dx < 2; ++dx) {
            const int xx = std::min(x0 + dx, W - 1), yy = std::min(y0 + dy, H - 1);
            far = std::max(far, rb.depth[size_t(yy) * W + xx]);
          }
        const double z = s == kSurfaceNone ? kInf : pc.z;
        if (z > double(far) * 1.01 + 0.05) f.u[i] = f.v[i] = unknown;
      }
    }
  return f;
}

}  // namespace bvb
