// A scene directory's scene.txt: parse_scene_txt, what read_scene runs on the file's text.
#include "fuzz_target.h"
#include "scene/scene_io.h"

using namespace bvb;

BVB_FUZZ_TARGET {
  fuzz::parse_or_reject([&] {
    SceneData d;
    parse_scene_txt(fuzz::text_of(data, size), "scene.txt", &d);
    return d.frames;
  });
  return 0;
}
