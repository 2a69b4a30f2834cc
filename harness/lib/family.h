// A kernel family as the harness sees it: how to check it, how to benchmark it, and how to run it
// on a user's frames. Each family lives in harness/checks/<family>.cpp and registers itself with
// BVB_FAMILY; bfbench and the tests iterate over families().
#pragma once

#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "check.h"
#include "formats.h"
#include "image.h"

namespace bvb {

// --param K=V pairs, with typed getters; a key nobody asked for is an error.
class Params {
 public:
  void set(const std::string &kv);  // "K=V"; throws InputError
  int get_int(const std::string &key, int fallback, int lo, int hi);
  std::string get_str(const std::string &key, const std::string &fallback);
  bool has(const std::string &key) const { return values_.count(key) != 0; }
  void check_all_used() const;  // throws InputError naming the first unknown key

 private:
  std::map<std::string, std::string> values_;
  std::set<std::string> used_;
};

struct RunRequest {
  std::string kernel;
  std::vector<std::string> inputs;
  std::string output;
  Params params;
  int raw_width = 0, raw_height = 0;  // for raw UYVY inputs (--size WxH)
  // A colour frame given to a kernel of grey frames is an error unless this is set (run
  // --grey): then it is converted with BT.601 luma weights.
  bool grey_from_colour = false;
};

// What bfbench run executes: one call, and how its buffers become the output file.
struct RunPlan {
  CheckCall call;
  std::function<void(std::vector<std::vector<uint8_t>> &bufs, const std::string &path)> write;
  std::string summary;  // e.g. "160x120, 1 output frame"
  // What write() makes, for the names --out may have (formats.h); .npy is always possible:
  // bfbench run writes the chosen buffer itself.
  OutputKind kind = OutputKind::Image;
};

struct Family {
  std::string name;
  std::vector<std::string> kernels;
  std::function<void(Checker &)> check;
  // A representative call of `kernel` on a w x h frame, for bfbench bench; empty kernel name in
  // the result means the kernel has no bench at that size.
  std::function<CheckCall(const std::string &kernel, int w, int h, Rng &rng)> bench_call;
  // The kernel's stated lower bound in cycles at w x h (what the issue width allows), 0 if none.
  std::function<double(const std::string &kernel, int w, int h)> lower_bound;
  std::function<RunPlan(RunRequest &req)> plan_run;
};

std::vector<const Family *> &families();
const Family *family_of(const std::string &kernel);
bool register_family(const Family *f);
#define BVB_FAMILY(var) static const bool var##_registered_ = ::bvb::register_family(&var)

// The smallest frame a kernel's bench call takes: the kernel's stated minimum (its header), or
// what the bench call builds around it (ncc's search windows, the Harris corners lk_track
// tracks), and whether the width must be even (UYVY pairs). Below it the assembly may fault or
// hang, so bench and budgets refuse such sizes as bad input instead of blaming the kernel.
struct SizeRule {
  int min_w = 1, min_h = 1;
  bool even_width = false;
};
// Every kernel with a bench call has an entry; nullptr for one without.
const SizeRule *bench_size_rule(const std::string &kernel);
// "" when the kernel can be benched at w x h, else why not, naming its minimum.
std::string bench_size_problem(const std::string &kernel, int w, int h);

// Reads an input frame for bfbench run in the format its name says (formats.h); raw .uyvy needs
// the size and gives its Y plane.
Image read_frame(const std::string &path, int raw_w, int raw_h);
// Input i of a run as a grey frame: a colour one is an InputError naming the kernel and what it
// takes, unless req.grey_from_colour asks for the conversion.
Image read_input(const RunRequest &req, size_t i);

// A call's buffer as a NumPy array: its element type and sign, shape (rows, elements per row)
// or (rows, pixels per row, channels) from its view, the stride's padding left out; a buffer
// without a 2-D view is flat.
NpyArray npy_of_buffer(const Buffer &b, const std::vector<uint8_t> &data);

}  // namespace bvb
