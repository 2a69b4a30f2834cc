// The one option parser of every bfbench command (harness/lib/options.h) and the names it
// reads (harness/lib/names.h): what it accepts, what it refuses with which message, and the
// help it makes from the declarations.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "names.h"
#include "options.h"

namespace bvb {
namespace {

// A command with one option of every kind, as the commands declare them.
struct Demo {
  bool flag = false;
  int count = 3;
  double alpha = 8;
  std::string text = "default", timing;
  Size size{320, 240};
  std::vector<std::string> params, operands;
  std::vector<Size> sizes;
  CommandLine cl{"demo"};

  explicit Demo(size_t min_operands = 0, size_t max_operands = 2) {
    cl.about("A command for the tests.")
        .flag("--flag", &flag, "a flag")
        .integer("-n,--count", "N", 1, 10, &count, "a count")
        .number("--alpha", "A", 8, 256, &alpha, "a number")
        .text("--text", "WORD", &text, "a word")
        .choice("--timing", {"none", "bf537"}, &timing, "a model")
        .size("--size", &size, "one size")
        .texts("--param", "K=V", &params, "a parameter")
        .sizes("--sizes", &sizes, "sizes")
        .operands("THING", &operands, min_operands, max_operands, "(demo list)");
  }
  bool parse(const std::vector<std::string> &args) { return cl.parse(args); }
  // The message parse throws, or "" when it throws nothing.
  std::string error(const std::vector<std::string> &args) {
    try {
      parse(args);
    } catch (const UsageError &e) {
      return e.what();
    }
    return "";
  }
};

TEST(Options, EveryKindOfValueIsParsed) {
  Demo d;
  ASSERT_TRUE(d.parse({"a", "--flag", "-n", "7", "--alpha=12.5", "--text", "w", "--timing", "none", "--size", "64x48",
                       "--param", "x=1", "b", "--param=y=2", "--sizes", "1x2", "--sizes", "3x4"}));
  EXPECT_TRUE(d.flag);
  EXPECT_EQ(d.count, 7);
  EXPECT_EQ(d.alpha, 12.5);
  EXPECT_EQ(d.text, "w");
  EXPECT_EQ(d.timing, "none");
  EXPECT_EQ(d.size.w, 64);
  EXPECT_EQ(d.size.h, 48);
  EXPECT_EQ(d.params, (std::vector<std::string>{"x=1", "y=2"}));
  ASSERT_EQ(d.sizes.size(), 2u);
  EXPECT_EQ(d.sizes[1].w, 3);
  EXPECT_EQ(d.sizes[1].h, 4);
  EXPECT_EQ(d.operands, (std::vector<std::string>{"a", "b"}));
  EXPECT_TRUE(d.cl.given("--count"));
  Demo e;
  ASSERT_TRUE(e.parse({"-n=4", "--param=k=v=w"}));
  EXPECT_EQ(e.count, 4);
  EXPECT_EQ(e.params, (std::vector<std::string>{"k=v=w"}));
  EXPECT_TRUE(d.cl.given("-n"));
}

TEST(Options, DefaultsStayWhenNotGiven) {
  Demo d;
  ASSERT_TRUE(d.parse({}));
  EXPECT_FALSE(d.flag);
  EXPECT_EQ(d.count, 3);
  EXPECT_EQ(d.text, "default");
  EXPECT_EQ(d.size.w, 320);
  EXPECT_FALSE(d.cl.given("--size"));
  EXPECT_FALSE(d.cl.given("--flag"));
}

TEST(Options, UnknownOptionIsRefused) {
  EXPECT_EQ(Demo().error({"--bogus"}), "unknown option --bogus (bfbench demo --help)");
  EXPECT_EQ(Demo().error({"--bogus=1"}), "unknown option --bogus (bfbench demo --help)");
  EXPECT_EQ(Demo().error({"-x"}), "unknown option -x (bfbench demo --help)");
  // A prefix of a declared name is not that option.
  EXPECT_EQ(Demo().error({"--fla"}), "unknown option --fla (bfbench demo --help)");
}

TEST(Options, MissingValueIsRefused) {
  EXPECT_EQ(Demo().error({"--text"}), "--text needs a value (WORD)");
  EXPECT_EQ(Demo().error({"a", "-n"}), "-n needs a value (N)");
  EXPECT_EQ(Demo().error({"--param"}), "--param needs a value (K=V)");
}

TEST(Options, MalformedSizeIsRefused) {
  for (const char *bad : {"0x5", "5x0", "12x", "x3", "3x4x5", "3X4", " 3x4", "3x4 ", "+3x4", "-3x4", "3x-4", "4097x1",
                          "99999999999x1", "", "axb"}) {
    Demo d;
    EXPECT_EQ(d.error({"--size", bad}), std::string("--size wants WxH (1..4096), got '") + bad + "'") << bad;
    EXPECT_EQ(d.size.w, 320) << bad << ": a refused size changed the value";
  }
  EXPECT_EQ(Demo().error({"--sizes", "1x1", "--sizes", "1x"}), "--sizes wants WxH (1..4096), got '1x'");
  Demo d;
  ASSERT_TRUE(d.parse({"--size", "4096x1"}));
  EXPECT_EQ(d.size.w, 4096);
}

TEST(Options, MalformedNumbersAreRefused) {
  for (const char *bad : {"0", "11", "x", "", "7x", " 7", "+7", "1e1", "7.0", "99999999999999999999"})
    EXPECT_EQ(Demo().error({"-n", bad}), std::string("-n wants an integer in 1..10, got '") + bad + "'") << bad;
  for (const char *bad : {"7.9", "257", "eight", "", "nan", "inf", "8x"})
    EXPECT_EQ(Demo().error({"--alpha", bad}), std::string("--alpha wants a number in 8..256, got '") + bad + "'") << bad;
  EXPECT_EQ(Demo().error({"--timing", "fast"}), "--timing wants none or bf537, got 'fast'");
}

TEST(Options, RepeatedOptionIsRefusedUnlessRepeatable) {
  EXPECT_EQ(Demo().error({"--text", "a", "--text", "b"}), "--text given more than once");
  // Under either of its names.
  EXPECT_EQ(Demo().error({"-n", "1", "--count=2"}), "--count given more than once");
  EXPECT_EQ(Demo().error({"--flag", "--flag"}), "--flag given more than once");
  Demo d;
  ASSERT_TRUE(d.parse({"--param", "a=1", "--param", "a=2", "--param", "b=3"}));
  EXPECT_EQ(d.params, (std::vector<std::string>{"a=1", "a=2", "b=3"}));
}

TEST(Options, FlagTakesNoValue) { EXPECT_EQ(Demo().error({"--flag=1"}), "--flag takes no value"); }

TEST(Options, OperandCounts) {
  EXPECT_EQ(Demo().error({"a", "b", "c"}), "demo takes at most 2 THING (demo list)");
  EXPECT_EQ(Demo(1, 1).error({}), "demo takes one THING (demo list)");
  EXPECT_EQ(Demo(1, 1).error({"a", "b"}), "demo takes one THING (demo list)");
  EXPECT_EQ(Demo(2, 3).error({"a"}), "demo takes at least 2 THING (demo list)");
  // A command that declares no operands takes none.
  CommandLine none("plain");
  EXPECT_THROW(none.parse({"stray"}), UsageError);
  EXPECT_TRUE(none.parse({}));
}

TEST(Options, RequiredOption) {
  std::string in;
  CommandLine cl("run");
  cl.text("--in", "FILE", &in, "input").required();
  try {
    cl.parse({});
    ADD_FAILURE() << "no error without --in";
  } catch (const UsageError &e) {
    EXPECT_STREQ(e.what(), "run needs --in FILE");
  }
  CommandLine ok("run");
  ok.text("--in", "FILE", &in, "input").required();
  EXPECT_TRUE(ok.parse({"--in", "a.pgm"}));
  EXPECT_EQ(in, "a.pgm");
}

TEST(Options, HelpIsMadeFromTheDeclarations) {
  Demo d;
  const std::string h = d.cl.help();
  EXPECT_EQ(h.rfind("usage: bfbench demo [THING...] [--flag] [-n N] [--alpha A] [--text WORD] [--timing none|bf537]", 0),
            0u)
      << h;
  EXPECT_NE(h.find("[--param K=V]..."), std::string::npos) << h;
  EXPECT_NE(h.find("\nA command for the tests.\n"), std::string::npos) << h;
  EXPECT_NE(h.find("\n  -n, --count N"), std::string::npos) << h;
  EXPECT_NE(h.find("a count\n"), std::string::npos) << h;
  EXPECT_NE(h.find("\n  --size WxH"), std::string::npos) << h;
  EXPECT_NE(h.find("a parameter (repeatable)"), std::string::npos) << h;
  EXPECT_NE(h.find("\n  -h, --help"), std::string::npos) << h;
  EXPECT_NE(h.find(kExitStatusHelp), std::string::npos) << h;
  // The usage lines wrap between options, never inside one: each line's brackets close on it.
  const std::string usage = h.substr(0, h.find("\n\n"));
  EXPECT_NE(usage.find('\n'), std::string::npos) << "the usage fits one line: nothing tests the wrapping";
  for (size_t a = 0, b; a < usage.size(); a = b + 1) {
    b = std::min(usage.find('\n', a), usage.size());
    const std::string line = usage.substr(a, b - a);
    EXPECT_EQ(std::count(line.begin(), line.end(), '['), std::count(line.begin(), line.end(), ']')) << line;
  }
  for (size_t a = 0, b; a < h.size(); a = b + 1) {
    b = h.find('\n', a);
    EXPECT_LE(b - a, 96u) << "a help line over 96 columns: " << h.substr(a, b - a);
  }
}

TEST(Options, UsageWrapsBetweenOptions) {
  // Forty options of two words each, over many lines: a wrap between words would split some.
  CommandLine many("many");
  std::vector<std::string> values(40);
  for (size_t i = 0; i < values.size(); ++i)
    many.text("--option" + std::to_string(i * 7), "VALUE", &values[i], "one of many");
  const std::string h = many.help();
  const std::string usage = h.substr(0, h.find("\n\n"));
  EXPECT_GT(std::count(usage.begin(), usage.end(), '\n'), 5) << usage;
  for (size_t a = 0, b; a < usage.size(); a = b + 1) {
    b = std::min(usage.find('\n', a), usage.size());
    const std::string line = usage.substr(a, b - a);
    EXPECT_LE(line.size(), 96u) << line;
    EXPECT_EQ(std::count(line.begin(), line.end(), '['), std::count(line.begin(), line.end(), ']')) << line;
  }
}

TEST(Options, HelpWinsAndStopsTheCommand) {
  for (const std::vector<std::string> &args : std::vector<std::vector<std::string>>{
           {"--help"}, {"-h"}, {"--bogus", "--help"}, {"--size", "0x0", "-h"}, {"a", "b", "c", "--help"}}) {
    Demo d;
    testing::internal::CaptureStdout();
    bool run = true;
    EXPECT_NO_THROW(run = d.parse(args));
    const std::string out = testing::internal::GetCapturedStdout();
    EXPECT_FALSE(run);
    EXPECT_EQ(out, d.cl.help());
    EXPECT_FALSE(d.flag);
  }
}

TEST(Options, DeclaringANameTwiceIsAProgrammingError) {
  bool a = false, b = false;
  CommandLine cl("x");
  cl.flag("--a", &a, "a");
  EXPECT_THROW(cl.flag("--a", &b, "again"), std::logic_error);
  EXPECT_THROW(cl.flag("--help", &b, "reserved"), std::logic_error);
  EXPECT_THROW(cl.flag("b", &b, "no dash"), std::logic_error);
}

TEST(Options, RunCommandMapsErrorsToExitTwoAndPassesStatusOn) {
  testing::internal::CaptureStderr();
  EXPECT_EQ(run_command("demo", [] { return int(kExitFailed); }), 1);
  EXPECT_EQ(run_command("demo", []() -> int { throw UsageError("bad\nthing"); }), 2);
  EXPECT_EQ(run_command("demo", []() -> int { throw InputError("no file"); }), 2);
  EXPECT_EQ(run_command("demo", []() -> int { throw std::runtime_error("oops"); }), 2);
  EXPECT_EQ(run_command("demo", []() -> int { throw CallFailed("frame 3: wrong"); }), 1);
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(err,
            "bfbench demo: bad\\x0athing\nbfbench demo: no file\nbfbench demo: internal error: oops\n"
            "bfbench demo: frame 3: wrong\n");
}

TEST(Names, SizesRoundTrip) {
  EXPECT_EQ(size_name(160, 120), "160x120");
  EXPECT_EQ(size_name(Size{1, 4096}), "1x4096");
  Size s{0, 0};
  ASSERT_TRUE(parse_size(size_name(640, 480), 4096, &s));
  EXPECT_EQ(s.w, 640);
  EXPECT_EQ(s.h, 480);
  EXPECT_FALSE(parse_size("641x480", 640, &s));
  EXPECT_EQ(s.w, 640) << "a refused size changed *out";
  ASSERT_TRUE(parse_size_prefix("320x240 N=10, per iteration", &s));
  EXPECT_EQ(s.w, 320);
  EXPECT_EQ(s.h, 240);
  EXPECT_FALSE(parse_size_prefix("320x240N=10", &s));
  EXPECT_FALSE(parse_size_prefix("robot 320x240", &s));
}

TEST(Names, CaseIdsRoundTrip) {
  EXPECT_EQ(case_id("sobel3x3_u8", 17), "sobel3x3_u8:17");
  std::string k;
  uint64_t n = 0;
  ASSERT_TRUE(parse_case_id(case_id("add_sat_u8", 5), &k, &n));
  EXPECT_EQ(k, "add_sat_u8");
  EXPECT_EQ(n, 5u);
  for (const char *bad : {"add_sat_u8", "add_sat_u8:", ":5", "add_sat_u8:5x", "add_sat_u8:-5", "a:99999999999999999999"})
    EXPECT_FALSE(parse_case_id(bad, &k, &n)) << bad;
  EXPECT_EQ(case_kernel("a:b:7"), "a:b");
}

TEST(Names, BudgetKeys) {
  const std::string key = budget_key("hornschunck", "asm", "160x120 N=10");
  EXPECT_EQ(key, "hornschunck/asm/160x120 N=10");
  EXPECT_EQ(budget_key_kernel(key), "hornschunck");
  EXPECT_EQ(budget_key_case(key), "160x120 N=10");
}

}  // namespace
}  // namespace bvb
