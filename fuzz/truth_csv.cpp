// A scene directory's truth.csv: parse_truth_csv, what read_scene runs on the file's text.
#include "fuzz_target.h"
#include "scene/scene_io.h"

using namespace bvb;

BVB_FUZZ_TARGET {
  fuzz::parse_or_reject([&] { return parse_truth_csv(fuzz::text_of(data, size), "truth.csv"); });
  return 0;
}
