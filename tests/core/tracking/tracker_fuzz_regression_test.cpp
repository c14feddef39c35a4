// The radar tracker fuzz invariants (tests/fuzz/radar_tracker_invariants.hpp)
// under the normal build: every input of the fuzz corpus, findings included,
// and a seeded batch of random inputs, in double, float and Q31.32.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <vector>

#include "fuzz/radar_tracker_invariants.hpp"

namespace {

std::vector<std::uint8_t> read_file(const std::filesystem::path& p) {
  std::ifstream f(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

}  // namespace

SCENARIO("every radar tracker fuzz corpus input keeps the tracker invariants", "[tracker][fuzz]") {
  const std::filesystem::path dir = std::filesystem::path(KESTREL_FUZZ_CORPUS_DIR) / "radar_tracker";
  REQUIRE(std::filesystem::is_directory(dir));
  int inputs = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const auto bytes = read_file(entry.path());
    INFO(entry.path().filename().string() << " (" << bytes.size() << " bytes)");
    const char* why = kestrel::test::check_radar_tracker_invariants(bytes);
    INFO((why != nullptr ? why : "ok"));
    CHECK(why == nullptr);
    ++inputs;
  }
  CHECK(inputs >= 8);
}

SCENARIO("seeded random inputs keep the radar tracker invariants", "[tracker][fuzz]") {
  std::mt19937_64 rng(20261201);
  for (int n = 0; n < 150; ++n) {
    std::vector<std::uint8_t> bytes(32 + rng() % 480);
    for (auto& b : bytes) b = static_cast<std::uint8_t>(rng());
    // Most ops step the clock by one scan period, as a sensor does.
    for (std::size_t i = 0; i < bytes.size(); i += 7) bytes[i] &= 0xFC;
    const char* why = kestrel::test::check_radar_tracker_invariants(bytes);
    INFO("input " << n << ": " << (why != nullptr ? why : "ok"));
    CHECK(why == nullptr);
  }
}
