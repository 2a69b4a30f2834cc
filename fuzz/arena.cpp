// Arena files (frames/arenas/*.txt, a scene's arena.txt): parse_arena on the text, less the
// texture it builds from texture_seed (deterministic, no input bytes; about 6 MB and tens of
// milliseconds a seed, which would make the target a texture benchmark).
#include "fuzz_target.h"
#include "scene/world.h"

using namespace bvb;

BVB_FUZZ_TARGET {
  const auto w = fuzz::parse_or_reject([&] { return parse_arena_untextured(fuzz::text_of(data, size), "fuzz-arena.txt"); });
  if (!w) return 0;
  // format_arena is documented as canonical: what it writes reads back and formats the same.
  const std::string text = format_arena(*w);
  const auto back = fuzz::parse_or_reject([&] { return parse_arena_untextured(text, "round trip"); });
  if (!back) fuzz::finding("format_arena wrote an arena parse_arena rejects:\n" + text);
  if (format_arena(*back) != text) fuzz::finding("format_arena then parse_arena changed the arena:\n" + text);
  return 0;
}
