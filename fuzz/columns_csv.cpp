// A scene directory's columns.csv: parse_columns_csv, what read_scene runs on the file's text,
// for the frame count and size of the repository's scenes (frames/scenes: 25 frames, 160x120),
// which scene.txt would give it.
#include "fuzz_target.h"
#include "scene/scene_io.h"

using namespace bvb;

BVB_FUZZ_TARGET {
  fuzz::parse_or_reject([&] { return parse_columns_csv(fuzz::text_of(data, size), "columns.csv", 25, 160, 120); });
  return 0;
}
