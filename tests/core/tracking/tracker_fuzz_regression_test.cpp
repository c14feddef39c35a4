// SPDX-License-Identifier: Apache-2.0
// The tracker fuzz invariants (tests/fuzz/*_tracker_invariants.hpp) under
// the normal build: every input of each fuzz corpus, findings included, and
// a seeded batch of random inputs, for the radar tracker (double, float,
// Q31.32), the PCL tracker and the sonar tracker (double, float).
#include <catch2/catch.hpp>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "fuzz/pcl_tracker_invariants.hpp"
#include "fuzz/radar_tracker_invariants.hpp"
#include "fuzz/sonar_tracker_invariants.hpp"

namespace {

using kestrel::test::FuzzTally;

std::vector<std::uint8_t> read_file(const std::filesystem::path& p) {
  std::ifstream f(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

/// Runs `check` on every file of corpus/<name>; returns how many there were.
template <class Check>
int replay_corpus(const char* name, Check check) {
  const std::filesystem::path dir = std::filesystem::path(KESTREL_FUZZ_CORPUS_DIR) / name;
  REQUIRE(std::filesystem::is_directory(dir));
  int inputs = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const auto bytes = read_file(entry.path());
    INFO(entry.path().filename().string() << " (" << bytes.size() << " bytes)");
    const char* why = check(bytes);
    INFO((why != nullptr ? why : "ok"));
    CHECK(why == nullptr);
    ++inputs;
  }
  return inputs;
}

/// A random input in the frame format of the PCL and sonar harnesses
/// that mostly keeps to the sensor's rhythm, so tracks form between the
/// faults: 7 frames in 8 step one period (op bits 0-1 clear) and 3 items in
/// 4 are target detections (item bit 0 clear); every other bit is random.
/// @param operand_bytes bytes an item with bit 0 set reads after its own.
std::vector<std::uint8_t> rhythmic_input(std::mt19937_64& rng, int frames, int (*operand_bytes)(std::uint8_t)) {
  static constexpr int kTimeOperandBytes[4] = {0, 2, 8, 4};
  std::vector<std::uint8_t> out;
  const auto push_random = [&](int n) {
    for (int i = 0; i < n; ++i) out.push_back(static_cast<std::uint8_t>(rng()));
  };
  for (int k = 0; k < frames; ++k) {
    auto op = static_cast<std::uint8_t>(rng());
    if (rng() % 8 != 0) op &= 0xFC;
    out.push_back(op);
    push_random(kTimeOperandBytes[op & 3u]);
    const int items = (op >> 2) & 15;
    for (int i = 0; i < items; ++i) {
      auto b = static_cast<std::uint8_t>(rng());
      if (rng() % 4 != 0) b &= 0xFE;
      out.push_back(b);
      if (b & 1u) push_random(operand_bytes(b));
    }
  }
  return out;
}

// Bytes a non-target item reads (pcl_tracker_invariants.hpp,
// sonar_tracker_invariants.hpp).
int pcl_operand_bytes(std::uint8_t b) { return (b & 2u) == 0 ? 4 : 10; }
int sonar_operand_bytes(std::uint8_t b) { return (b & 0x80u) != 0 ? 5 : 4; }

}  // namespace

SCENARIO("every radar tracker fuzz corpus input keeps the tracker invariants", "[tracker][fuzz]") {
  FuzzTally imm;
  const int inputs = replay_corpus("radar_tracker", [&imm](std::span<const std::uint8_t> bytes) {
    return kestrel::test::check_radar_tracker_invariants(bytes, &imm);
  });
  CHECK(inputs >= 8);
  // The corpus takes the IMM tracker to confirmed tracks and to refused
  // and over-capacity frames, so its invariants are checked where they bite.
  INFO("IMM: frames " << imm.frames << ", reports " << imm.reports << ", refused " << imm.refused << ", cut "
                      << imm.truncated);
  CHECK(imm.reports > 500);
  CHECK(imm.refused >= 20);
  CHECK(imm.truncated >= 20);
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

SCENARIO("every PCL tracker fuzz corpus input keeps the tracker invariants", "[pcl][tracker][fuzz]") {
  FuzzTally tally;
  const int inputs = replay_corpus("pcl_tracker", [&tally](std::span<const std::uint8_t> bytes) {
    return kestrel::test::check_pcl_tracker_invariants(bytes, &tally);
  });
  CHECK(inputs >= 7);
  // The corpus reaches what the invariants are about: confirmed tracks that
  // report, refused frames, over-capacity frames.
  CHECK(tally.reports > 800);
  CHECK(tally.refused >= 10);
  CHECK(tally.truncated >= 20);
}

SCENARIO("seeded random inputs keep the PCL tracker invariants", "[pcl][tracker][fuzz]") {
  std::mt19937_64 rng(20261202);
  FuzzTally tally;
  for (int n = 0; n < 150; ++n) {
    const auto bytes = rhythmic_input(rng, 1 + static_cast<int>(rng() % 48), pcl_operand_bytes);
    const char* why = kestrel::test::check_pcl_tracker_invariants(bytes, &tally);
    INFO("input " << n << ": " << (why != nullptr ? why : "ok"));
    CHECK(why == nullptr);
  }
  CHECK(tally.reports > 100);
  CHECK(tally.refused > 100);
}

SCENARIO("every sonar tracker fuzz corpus input keeps the tracker invariants", "[sonar][tracker][fuzz]") {
  FuzzTally tally;
  const int inputs = replay_corpus("sonar_tracker", [&tally](std::span<const std::uint8_t> bytes) {
    return kestrel::test::check_sonar_tracker_invariants(bytes, &tally);
  });
  CHECK(inputs >= 8);
  CHECK(tally.reports > 200);
  CHECK(tally.refused >= 10);
  CHECK(tally.truncated >= 10);
}

SCENARIO("seeded random inputs keep the sonar tracker invariants", "[sonar][tracker][fuzz]") {
  std::mt19937_64 rng(20261203);
  FuzzTally tally;
  for (int n = 0; n < 150; ++n) {
    const auto bytes = rhythmic_input(rng, 1 + static_cast<int>(rng() % 24), sonar_operand_bytes);
    const char* why = kestrel::test::check_sonar_tracker_invariants(bytes, &tally);
    INFO("input " << n << ": " << (why != nullptr ? why : "ok"));
    CHECK(why == nullptr);
  }
  CHECK(tally.reports > 100);
  CHECK(tally.refused > 100);
}
