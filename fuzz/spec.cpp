// Scene spec strings (bfbench scene --spec, pipeline --spec, a scene.txt's spec line):
// parse_scene_spec, then the path's script expanded into steps as SceneGenerator does.
#include "fuzz_target.h"
#include "scene/scene_io.h"

using namespace bvb;

BVB_FUZZ_TARGET {
  const auto s = fuzz::parse_or_reject([&] { return parse_scene_spec(fuzz::text_of(data, size)); });
  if (!s) return 0;
  // format_scene_spec is documented to round-trip: parse_scene_spec(format_scene_spec(s)) == s.
  const std::string text = format_scene_spec(*s);
  const auto back = fuzz::parse_or_reject([&] { return parse_scene_spec(text); });
  if (!back) fuzz::finding("format_scene_spec wrote a spec parse_scene_spec rejects: " + text);
  if (format_scene_spec(*back) != text) fuzz::finding("format_scene_spec then parse_scene_spec changed the spec: " + text);
  if (s->path != "avoid")
    fuzz::parse_or_reject([&] {
      return expand_script(path_script(s->path, s->length_in, s->angle_deg, s->side_in, s->square_left),
                           s->speed_in, s->turn_rate_deg);
    });
  return 0;
}
