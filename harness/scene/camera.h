// The robot's pose and the camera model of the scene generator.
//
// Units: inches and degrees throughout (the seed paper's units); kMetresPerInch converts.
//
// World frame: right-handed, z up, the floor is the plane z = 0. x and y span the floor; a
// pose's heading is the angle of the robot's forward direction from the +x axis, counter-
// clockwise positive (seen from above), so a left turn increases the heading and +y lies to
// the left of a robot heading 0. Headings are not wrapped: a path's heading is cumulative.
//
// Camera: a pinhole on the robot's centre line, cam_offset_in ahead of the wheel-axle centre
// (the point a turn in place pivots about), cam_height_in above the floor, its optical axis
// tilt_deg below the horizontal, no roll. Image coordinates: x to the right, y down, the centre
// of pixel (i, j) at (i, j); a camera-frame point (X right, Y down, Z along the optical axis)
// projects to x = cx + fx X/Z, y = cy + fy Y/Z.
//
// Default intrinsics (Camera::standard): fx = fy = 0.875 * width, cx = (width-1)/2,
// cy = (height-1)/2. At 160x120 that is fx = fy = 140 px, a horizontal field of view of
// 2 atan(80/140) = 59.5 deg and a vertical one of 46.4 deg (320x240: fx = fy = 280, the same
// angles). The SRV-1's own lens is ~90 deg wide, more than a distortion-free pinhole models
// well; 60 deg is a common webcam-class view. The camera sits 4 in above the floor tilted
// 10 deg down: at 160x120 the horizon is row cy - fy tan(10 deg) = 34.8 and the bottom row
// sees the floor 6.2 in ahead of the camera.
#pragma once

#include <cmath>

namespace bvb {

constexpr double kMetresPerInch = 0.0254;
constexpr double kPi = 3.14159265358979323846;
inline double deg2rad(double d) { return d * (kPi / 180.0); }
inline double rad2deg(double r) { return r * (180.0 / kPi); }

struct Vec2 {
  double x = 0, y = 0;
};
struct Vec3 {
  double x = 0, y = 0, z = 0;
};
inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// The robot on the floor: position of the wheel-axle centre and heading (see above).
struct Pose {
  double x_in = 0, y_in = 0, heading_deg = 0;
};

constexpr double kDefaultFocalPerWidth = 0.875;  // fx = fy = 0.875 * width
constexpr double kDefaultCamHeightIn = 4.0;
constexpr double kDefaultTiltDeg = 10.0;
constexpr double kDefaultCamOffsetIn = 0.0;

struct Camera {
  int width = 160, height = 120;
  double fx = 140, fy = 140, cx = 79.5, cy = 59.5;  // pixels
  double cam_height_in = kDefaultCamHeightIn;       // optical centre above the floor
  double tilt_deg = kDefaultTiltDeg;                // optical axis below the horizontal
  double cam_offset_in = kDefaultCamOffsetIn;       // optical centre ahead of the axle centre

  static Camera standard(int w, int h) {
    Camera c;
    c.width = w;
    c.height = h;
    c.fx = c.fy = kDefaultFocalPerWidth * w;
    c.cx = (w - 1) * 0.5;
    c.cy = (h - 1) * 0.5;
    return c;
  }
};

// The camera placed at a pose: optical centre and camera axes in world coordinates.
// The ray through image point (x, y) is centre + t * ray(x, y); because ray() has unit
// component along the optical axis, t is the camera-frame depth Z of the point it reaches.
struct CameraView {
  Vec3 centre, xc, yc, zc;  // xc: image right, yc: image down, zc: optical axis
  double fx, fy, cx, cy;

  CameraView(const Camera &cam, const Pose &pose) : fx(cam.fx), fy(cam.fy), cx(cam.cx), cy(cam.cy) {
    const double h = deg2rad(pose.heading_deg), t = deg2rad(cam.tilt_deg);
    const Vec3 f{std::cos(h), std::sin(h), 0}, right{std::sin(h), -std::cos(h), 0}, up{0, 0, 1};
    centre = Vec3{pose.x_in, pose.y_in, cam.cam_height_in} + cam.cam_offset_in * f;
    xc = right;
    zc = std::cos(t) * f - std::sin(t) * up;
    yc = -std::sin(t) * f - std::cos(t) * up;
  }
  Vec3 ray(double x, double y) const {
    return zc + ((x - cx) / fx) * xc + ((y - cy) / fy) * yc;
  }
  // Camera-frame coordinates of a world point.
  Vec3 to_camera(Vec3 p) const {
    const Vec3 v = p - centre;
    return {dot(v, xc), dot(v, yc), dot(v, zc)};
  }
  // Image position of a world point; false when it is not in front of the camera.
  bool project(Vec3 p, double &x, double &y) const {
    const Vec3 c = to_camera(p);
    if (!(c.z > 1e-9)) return false;
    x = cx + fx * c.x / c.z;
    y = cy + fy * c.y / c.z;
    return true;
  }
};

}  // namespace bvb
