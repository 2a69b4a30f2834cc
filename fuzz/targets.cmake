# The fuzz targets, read by the clang build (fuzz/CMakeLists.txt) and by the main build's tests
# (fuzz/driver.cmake). A target NAME is fuzz/NAME.cpp; adding one is a source file, a line in
# BVB_FUZZ_TARGETS and its two settings here:
#   BVB_FUZZ_<NAME>_SEEDS    its seed corpus: globs under the source tree (those under
#                            ../shared/frames-real count only where the real frames are present).
#                            The repository's files, and in fuzz/seeds/NAME/ small files and
#                            edge values (the largest numbers a field takes, inf, CRLF) that
#                            mutation alone rarely reaches.
#   BVB_FUZZ_<NAME>_MAX_LEN  libFuzzer's -max_len: longer seeds are cut to it. Small enough to
#                            keep the run fast, large enough for every header and a few rows.
#   BVB_FUZZ_<NAME>_DICT     a libFuzzer -dict (optional; the text formats use numbers.dict)
#   BVB_FUZZ_<NAME>_LIBS     what it links besides bvb_host (optional)
set(BVB_FUZZ_TARGETS pnm png npy uyvy flo arena spec scene_txt truth_csv columns_csv budgets)

set(BVB_FUZZ_pnm_SEEDS fuzz/seeds/pnm/* frames/scenes/*/*.pgm
    ../shared/frames-real/*/*.pgm ../shared/frames-real/*/*.ppm)
set(BVB_FUZZ_pnm_DICT fuzz/numbers.dict)
set(BVB_FUZZ_pnm_MAX_LEN 4096)

# Small hand-made files (fuzz/seeds/png: grey, RGB, palette) and the real frames' PNGs.
set(BVB_FUZZ_png_SEEDS fuzz/seeds/png/* ../shared/frames-real/*/*.png)
set(BVB_FUZZ_png_MAX_LEN 4096)

# fuzz/seeds/npy: the dtypes and shapes bfbench writes (u1 images, i2 flow, i4 responses).
set(BVB_FUZZ_npy_SEEDS fuzz/seeds/npy/*)
set(BVB_FUZZ_npy_DICT fuzz/numbers.dict)
set(BVB_FUZZ_npy_MAX_LEN 2048)

set(BVB_FUZZ_uyvy_SEEDS fuzz/seeds/uyvy/*)
set(BVB_FUZZ_uyvy_MAX_LEN 4096)

set(BVB_FUZZ_flo_SEEDS fuzz/seeds/flo/* ../shared/frames-real/*/*.flo)
set(BVB_FUZZ_flo_MAX_LEN 4096)

set(BVB_FUZZ_arena_SEEDS fuzz/seeds/arena/* frames/arenas/*.txt frames/scenes/*/arena.txt)
set(BVB_FUZZ_arena_DICT fuzz/numbers.dict)
set(BVB_FUZZ_arena_MAX_LEN 4096)

# fuzz/seeds/spec/: the spec lines of the repository's scenes (frames/scenes/*/scene.txt) and
# specs like the documentation's examples, covering every key.
set(BVB_FUZZ_spec_SEEDS fuzz/seeds/spec/*)
set(BVB_FUZZ_spec_DICT fuzz/numbers.dict)
set(BVB_FUZZ_spec_MAX_LEN 2048)

set(BVB_FUZZ_scene_txt_SEEDS fuzz/seeds/scene_txt/* frames/scenes/*/scene.txt)
set(BVB_FUZZ_scene_txt_DICT fuzz/numbers.dict)
set(BVB_FUZZ_scene_txt_MAX_LEN 4096)

set(BVB_FUZZ_truth_csv_SEEDS fuzz/seeds/truth_csv/* frames/scenes/*/truth.csv)
set(BVB_FUZZ_truth_csv_DICT fuzz/numbers.dict)
set(BVB_FUZZ_truth_csv_MAX_LEN 4096)

set(BVB_FUZZ_columns_csv_SEEDS fuzz/seeds/columns_csv/* frames/scenes/*/columns.csv)
set(BVB_FUZZ_columns_csv_DICT fuzz/numbers.dict)
set(BVB_FUZZ_columns_csv_MAX_LEN 4096)

set(BVB_FUZZ_budgets_SEEDS ci/budgets.json)
set(BVB_FUZZ_budgets_DICT fuzz/numbers.dict)
set(BVB_FUZZ_budgets_MAX_LEN 8192)
# Budget keys are checked against the kernel registry, which the kernel families fill.
set(BVB_FUZZ_budgets_LIBS bvb_checks)
