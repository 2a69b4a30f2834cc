// The arena the robot drives in: a flat textured floor, walls, boxes, cylinders and optional
// moving obstacles, read from the text files in frames/arenas/. Units and axes: camera.h.
//
// Arena file format (one item per line, '#' starts a comment, numbers in inches/degrees,
// colours 0..255 RGB before lighting, CONTRAST the amplitude of the surface texture as a
// fraction of the colour, default 0.2):
//   name NAME                                   optional, defaults to the file's stem
//   texture_seed N                              seed of the procedural floor/surface texture
//                                               (a whole number, 0..999999999999999999)
//   floor R G B CONTRAST                        floor colour and texture amplitude
//   background R G B                            what a ray that hits nothing sees
//   light AMBIENT DIFFUSE AZIMUTH ELEVATION     one distant light plus ambient (see below)
//   start X Y HEADING                           the robot's start pose (required)
//   wall X0 Y0 X1 Y1 HEIGHT THICKNESS R G B [CONTRAST]
//       a slab centred on the segment (X0,Y0)-(X1,Y1)
//   box CX CY SX SY ROT HEIGHT R G B [CONTRAST]
//       SX x SY footprint centred on (CX,CY), its SX side rotated ROT degrees from +x
//   cylinder CX CY RADIUS HEIGHT R G B [CONTRAST]
//   mover cylinder|box SIZE HEIGHT R G B X0 Y0 X1 Y1 SPEED [CONTRAST]
//       a second robot (cylinder of radius SIZE or box of side SIZE) shuttling between
//       (X0,Y0) and (X1,Y1) at SPEED inches per frame, at (X0,Y0) in frame 0
// Lighting: a surface with normal n gets AMBIENT + DIFFUSE * max(0, n . l), l the unit vector
// towards the light (AZIMUTH from +x counter-clockwise, ELEVATION above the floor).
// Everything stands on the floor: obstacles are vertical prisms with flat tops.
//
// For a ground segmentation to separate floor from obstacles, an obstacle's lit luma should
// stay at least ~40 levels away from the floor's: the bundled arenas use a mid-brown textured
// floor (luma ~120), near-white walls and dark or white obstacles.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "camera.h"

namespace bvb {

// The largest texture seed an arena file or a scene spec may give: 18 digits, read exactly (a
// double would round seeds above 2^53, and the reader must take whatever the writer wrote).
constexpr long long kMaxTextureSeed = 999999999999999999ll;

constexpr double kRobotRadiusIn = 3.0;  // the robot's collision disc (SRV-1: ~4 x 5 in chassis)

struct Rgb {
  float r = 0, g = 0, b = 0;
};

enum class ObstacleKind { Wall, Box, Cylinder };

struct Obstacle {
  ObstacleKind kind = ObstacleKind::Box;
  // Wall: x0 y0 x1 y1 thickness. Box: cx cy sx sy rot_deg. Cylinder: cx cy radius.
  std::array<double, 5> p{};
  double height_in = 0;
  Rgb color;
  double contrast = 0.2;
  int mover = -1;  // index of the World::movers entry this obstacle is, else -1

  // Derived by finalize(): walls and boxes as a convex footprint (counter-clockwise corners);
  // cylinders as centre + radius. centre is also the reference point a mover moves.
  std::array<Vec2, 4> corners{};
  Vec2 centre;
  double radius = 0;
  void finalize();
};

struct MoverDef {
  bool cylinder = true;
  double size_in = 2.5;  // radius of a cylinder, side of a box
  double height_in = 5;
  Rgb color{150, 25, 25};
  double contrast = 0.2;
  Vec2 a, b;                  // shuttles a -> b -> a ...
  double speed_in = 0.4;      // per frame
  Vec2 position(int frame) const;
};

struct Lighting {
  double ambient = 0.75, diffuse = 0.3, azimuth_deg = 30, elevation_deg = 60;
};

// A square, tileable intensity texture in [-1, 1] with its mip pyramid; 0.125 in per texel,
// 128 in period.
struct Texture {
  int size = 0;  // texels a side (a power of two)
  double texel_in = 0.125;
  std::vector<std::vector<float>> levels;  // levels[k] is (size >> k) squared
  // Trilinear sample at (u, v) inches; lod = log2(footprint in texels).
  float sample(double u, double v, double lod) const;
};
// Deterministic in the seed; shared, and cached for the kTextureCacheSeeds most recently used
// seeds (older ones are built again when asked for).
constexpr size_t kTextureCacheSeeds = 8;
std::shared_ptr<const Texture> make_texture(uint64_t seed);

struct World {
  std::string name;
  uint64_t texture_seed = 1;
  Rgb floor_color{140, 115, 90};
  double floor_contrast = 0.25;
  Rgb background{90, 95, 110};
  Lighting light;
  Pose start;
  std::vector<Obstacle> obstacles;  // static ones; world_at_frame appends the movers
  std::vector<MoverDef> movers;
  std::shared_ptr<const Texture> texture;  // set by parse_arena / finalize_world
};

// Parses an arena file's text; `where` names it in error messages (InputError, with line).
World parse_arena(const std::string &text, const std::string &where);
// The same without building the texture (tens of milliseconds, from texture_seed alone): all of
// the parsing, for the arena fuzz target.
World parse_arena_untextured(const std::string &text, const std::string &where);
// Canonical text of a world (parse_arena(format_arena(w)) reproduces w).
std::string format_arena(const World &w);
// NAME (a file frames/arenas/NAME.txt) or a path to an arena file (contains '/' or ends .txt).
// Arena directories searched: $BVB_ARENA_DIR, ./frames/arenas, then frames/arenas next to the
// running executable or any of its parent directories.
World load_arena(const std::string &name_or_path);
std::vector<std::string> arena_search_dirs();
std::vector<std::string> list_arenas();  // names found in the first directory that has any
// Builds the derived fields (footprints, texture) after editing a World in code.
void finalize_world(World &w);

// The world as it stands in frame `frame`: the static obstacles followed by one obstacle per
// mover, at its frame position (Obstacle::mover tells which).
World world_at_frame(const World &w, int frame);

// Whether the robot's disc of radius_in about the pose's axle centre overlaps an obstacle
// (touching, at distance exactly radius_in, is not a collision).
bool collides(const World &w, const Pose &pose, double radius_in = kRobotRadiusIn);
// The free run ahead: the least forward distance from the robot's front (radius_in ahead of the
// axle centre) to any obstacle inside the corridor of the robot's width (|lateral| <= radius_in,
// forward >= 0 from the axle centre). Negative when an obstacle already reaches into the
// corridor beside the robot's front half; +infinity when nothing is ahead.
// "Blocked" in the scene truth means corridor_clearance <= D (spec key block_dist).
double corridor_clearance(const World &w, const Pose &pose, double radius_in = kRobotRadiusIn);

}  // namespace bvb
