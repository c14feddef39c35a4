// SPDX-License-Identifier: Apache-2.0
// The CAT048 fuzz target's invariant checker run in every CTest over
// seeded mutations of valid CAT048 block streams, so CI exercises it
// without libFuzzer, and a check that the mutations reach every status.
#include <array>
#include <catch2/catch.hpp>
#include <cstdint>
#include <random>
#include <vector>

#include "asterix_builder.hpp"
#include "fuzz/asterix_cat048_invariants.hpp"

using kestrel::Status;
using kestrel::test::Bytes;

namespace {

Bytes random_block(std::mt19937& rng) {
  std::vector<kestrel::test::Cat048PlotSpec> plots(rng() % 40);
  std::uint32_t tod = rng() % (1u << 24);
  const bool one_frame = rng() % 4 == 0;  // reaches the frame's capacity
  for (auto& p : plots) {
    if (!one_frame && rng() % 3 == 0) tod = rng() % (1u << 24);
    p.sic = static_cast<std::uint8_t>(one_frame ? 1 : rng() % 2);
    p.tod_128 = tod;
    p.rho_256nm = static_cast<std::uint16_t>(rng());
    p.theta = static_cast<std::uint16_t>(rng());
    p.with_track_number = rng() % 2 == 0;
    p.with_doppler = rng() % 2 == 0;
    p.doppler_mps = static_cast<std::int16_t>(static_cast<int>(rng() % 1024) - 512);
    p.doppler_doubtful = rng() % 4 == 0;
  }
  return kestrel::test::cat048_block(plots);
}

void mutate(std::mt19937& rng, Bytes& b) {
  switch (rng() % 6) {
    case 0:  // flip bits anywhere
      for (int i = 0; i < 1 + static_cast<int>(rng() % 3); ++i) {
        const std::size_t bit = rng() % (b.size() * 8);
        b[bit / 8] = static_cast<std::uint8_t>(b[bit / 8] ^ (1u << (bit % 8)));
      }
      break;
    case 1: b.resize(rng() % b.size()); break;                  // truncate
    case 2: b[0] = static_cast<std::uint8_t>(rng() % 64); break;  // category
    case 3:                                                      // LEN
      b[1] = static_cast<std::uint8_t>(rng() % 2);
      b[2] = static_cast<std::uint8_t>(rng());
      break;
    case 4:  // a record byte, LEN kept right
      if (b.size() > 3) b[3 + rng() % (b.size() - 3)] = static_cast<std::uint8_t>(rng());
      break;
    default: break;  // intact
  }
}

}  // namespace

SCENARIO("the CAT048 reader keeps its invariants on mutated block streams", "[hal][fuzz][asterix]") {
  std::mt19937 rng(48);
  std::array<int, kestrel::kStatusCount> seen{};
  for (int i = 0; i < 3000; ++i) {
    Bytes stream;
    const int blocks = 1 + static_cast<int>(rng() % 3);
    for (int k = 0; k < blocks; ++k) {
      Bytes b = random_block(rng);
      mutate(rng, b);
      stream.insert(stream.end(), b.begin(), b.end());
    }
    const char* why = kestrel::test::check_cat048_reader_invariants(stream);
    INFO("stream " << i << ": " << (why ? why : ""));
    REQUIRE(why == nullptr);
    if (stream.size() > 3) {
      why = kestrel::test::check_cat048_record_invariants(std::span(stream).subspan(3));
      REQUIRE(why == nullptr);
    }
    // Tally what the first block gives, to show the mutations reach each status.
    kestrel::hal::asterix::Cat048Reader reader;
    std::size_t len = 0;
    const Status open = reader.open(stream, len);
    ++seen[static_cast<std::size_t>(open)];
    kestrel::hal::Frame f{};
    if (open == Status::kOk) {
      for (int c = 0; c < 100; ++c) {
        const Status s = reader.next(f);
        ++seen[static_cast<std::size_t>(s)];
        if (s == Status::kNoData || s == Status::kMalformedFrame) break;
      }
    }
  }
  for (const Status s : {Status::kOk, Status::kNoData, Status::kTruncated, Status::kMalformedFrame,
                         Status::kUnknownKind, Status::kTooManyCandidates}) {
    INFO(kestrel::to_string(s));
    CHECK(seen[static_cast<std::size_t>(s)] > 0);
  }
}
