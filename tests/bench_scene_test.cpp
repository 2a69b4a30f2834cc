// The hermetic bench inputs: SHA-256 against FIPS 180-2's examples, the SHA256SUMS check, the
// integer resampler, and the stored bench scene itself.
#include "scene/bench_scene.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "io.h"
#include "sha256.h"
#include "tempdir.h"

namespace bvb {
namespace {

TEST(Sha256, PublishedExamples) {
  // FIPS 180-2, appendix B: one block, two blocks, and a million 'a's (padding across blocks).
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha256_hex(std::string(1000000, 'a')), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  // 55 and 56 bytes: the last lengths with and without room for the length in the same block.
  EXPECT_NE(sha256_hex(std::string(55, 'x')), sha256_hex(std::string(56, 'x')));
}

void write(const std::string &path, const std::string &text) {
  std::ofstream(path, std::ios::binary) << text;
}

TEST(Sha256Sums, AcceptsTheListedBytesAndRejectsAnyOther) {
  const std::string dir = test_dir() + "sums";
  std::filesystem::create_directories(dir);
  write(dir + "/a.txt", "abc");
  write(dir + "/SHA256SUMS", "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad  a.txt\n");
  EXPECT_NO_THROW(verify_sha256sums(dir, {"a.txt"}));
  // A required file that is not listed, a changed byte, a malformed line.
  EXPECT_THROW(verify_sha256sums(dir, {"a.txt", "b.txt"}), InputError);
  write(dir + "/a.txt", "abd");
  try {
    verify_sha256sums(dir, {"a.txt"});
    FAIL() << "a changed file passed";
  } catch (const InputError &e) {
    EXPECT_NE(std::string(e.what()).find("a.txt: SHA-256"), std::string::npos) << e.what();
  }
  write(dir + "/SHA256SUMS", "ba7816bf  a.txt\n");
  EXPECT_THROW(verify_sha256sums(dir, {"a.txt"}), InputError);
  write(dir + "/SHA256SUMS", "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad  ../a.txt\n");
  EXPECT_THROW(verify_sha256sums(dir, {}), InputError);
}

TEST(ResampleGrey, AveragesWhenShrinkingAndInterpolatesWhenGrowing) {
  Image src(4, 2);
  const uint8_t px[] = {0, 10, 20, 31, 100, 110, 120, 131};
  std::copy(px, px + 8, src.data.begin());
  const Image half = resample_grey(src, 2, 1);
  // (0 + 10 + 100 + 110) / 4 = 55; (20 + 31 + 120 + 131) / 4 = 75.5, rounded up.
  EXPECT_EQ(half.data[0], 55);
  EXPECT_EQ(half.data[1], 76);
  EXPECT_EQ(resample_grey(src, 4, 2).data, src.data);
  // Growing 2 -> 4 along x: centres at -1/4, 1/4, 3/4, 5/4 source pixels, clamped at the edges.
  Image two(2, 1);
  two.data = {0, 200};
  const Image four = resample_grey(two, 4, 1);
  EXPECT_EQ(four.data, (std::vector<uint8_t>{0, 50, 150, 200}));
  // A constant image stays constant at any size.
  Image flat(7, 5, 1, 93);
  for (auto wh : {std::pair<int, int>{3, 2}, {16, 11}, {7, 9}}) {
    const Image r = resample_grey(flat, wh.first, wh.second);
    EXPECT_EQ(r.data, std::vector<uint8_t>(size_t(wh.first) * wh.second, 93));
  }
}

TEST(BenchScene, StoredFramesPassTheirHashesAndResampleToEverySize) {
  const BenchScene &s = bench_scene(320, 240);
  ASSERT_EQ(s.grey.size(), 2u);
  ASSERT_EQ(s.truth.size(), 2u);
  EXPECT_EQ(s.camera.width, 320);
  // The second frame is half an inch on: its pose and wheel ticks moved.
  EXPECT_DOUBLE_EQ(s.truth[1].pose.x_in - s.truth[0].pose.x_in, 0.5);
  EXPECT_GT(s.truth[1].left_ticks, 0);
  EXPECT_NE(s.grey[0].data, s.grey[1].data);
  for (auto wh : {std::pair<int, int>{160, 120}, {640, 480}}) {
    const BenchScene &r = bench_scene(wh.first, wh.second);
    ASSERT_EQ(r.grey.size(), 2u);
    EXPECT_EQ(r.grey[0].width, wh.first);
    EXPECT_EQ(r.grey[0].height, wh.second);
    EXPECT_EQ(r.camera.width, wh.first);
    EXPECT_DOUBLE_EQ(r.camera.fx / wh.first, s.camera.fx / 320);
  }
}

}  // namespace
}  // namespace bvb
