// Held-out scenes: arenas (room, obstacle layout, floor and light), floor texture seeds, start
// poses and paths drawn from one seed, so that the pipelines are judged on scenes their
// parameters were never tuned on (bfbench heldout, harness/pipelines/heldout.cpp).
//
// Every scene is a function of (seed, kind, index) alone: scene k of a seed is the same whatever
// other scenes or pipelines a run asks for, so a run's printed seed replays it exactly. The
// random numbers are SceneRng's (rng.h), integer arithmetic, so the layouts are the same on
// every host; only the rendering is floating point.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scene_io.h"
#include "world.h"

namespace bvb {

// A closed polygon driven as a script: leg i forward, then turn i in place. The turns all go
// one way (the polygon is convex) and add up to 360 degrees, so the robot ends where it
// started, facing as it started (to the 0.01 in and 0.01 degree the script is rounded to).
struct HeldoutPolygon {
  std::vector<double> legs_in;    // 3 to 8 legs of 12 to 36 in
  std::vector<double> turns_deg;  // exterior angles, each 15..165 degrees, signed (+ left)
  double length_in() const;
  std::string script() const;     // "F23.41+L71.2+F..."
};

struct HeldoutScene {
  std::string name;   // e.g. heldout-odometry-3
  World arena;        // finalized, with its texture
  SceneSpec spec;     // start, texture_seed, path, size, frames; spec.arena is `name`
  HeldoutPolygon polygon;  // odometry scenes only
  std::string describe() const;  // one line: room, obstacles, texture, start, path
};

// Closed polygons as described above (a few hundred tries at most; deterministic in rng).
HeldoutPolygon heldout_polygon(uint64_t seed);

// A room of 84 to 168 in a side with 3 to 9 boxes and cylinders (and sometimes a partition
// wall), a random floor colour, texture seed and light, and a start pose with room to move;
// driven in closed loop (spec.path = avoid) for `frames` frames. `base` gives the size and the
// rendering options.
HeldoutScene heldout_avoid_scene(uint64_t seed, int index, int frames, const SceneSpec &base);

// A closed polygon from a random start pose, in a room around it with 3 to 8 obstacles kept
// clear of the path (so the robot never drives into one), random floor, texture and light.
HeldoutScene heldout_odometry_scene(uint64_t seed, int index, const SceneSpec &base);

}  // namespace bvb
