// SPDX-License-Identifier: Apache-2.0
// The host feed over a whole stream: frames come back in order, garbage
// between frames is skipped to the next magic and reported once, a
// truncated tail is reported once, then the feed says kNoData.
#include <catch2/catch.hpp>
#include <vector>

#include "kestrel/host/stream_file_feed.hpp"
#include "scenarios/registry.hpp"
#include "stream/stream_writer.hpp"

using kestrel::Status;
using kestrel::host::StreamFileFeed;

SCENARIO("StreamFileFeed decodes a damaged stream without losing good frames", "[host_sim][feed]") {
  GIVEN("three S1 frames with 5 garbage bytes after the first and half a frame at the end") {
    auto frames = kestrel::sim::make_scenario("s1")->generate(1).frames;
    frames.resize(4);
    const auto one = kestrel::sim::encode_stream({frames[0]});
    const auto rest = kestrel::sim::encode_stream({frames[1], frames[2]});
    const auto tail = kestrel::sim::encode_stream({frames[3]});
    std::vector<std::uint8_t> bytes(one);
    bytes.insert(bytes.end(), {0x00, 0x4B, 0x53, 0xFF, 0x12});  // includes a false start of the magic
    bytes.insert(bytes.end(), rest.begin(), rest.end());
    bytes.insert(bytes.end(), tail.begin(), tail.begin() + static_cast<std::ptrdiff_t>(tail.size() / 2));
    StreamFileFeed feed(bytes);
    kestrel::hal::Frame f{};

    THEN("it yields: frame 0, one kBadMagic, frames 1 and 2, one kTruncated, then kNoData") {
      REQUIRE(feed.poll(f) == Status::kOk);
      CHECK(f.t_us == 0);
      CHECK(feed.poll(f) == Status::kBadMagic);
      REQUIRE(feed.poll(f) == Status::kOk);
      CHECK(f.t_us == 500000);
      REQUIRE(feed.poll(f) == Status::kOk);
      CHECK(f.t_us == 1000000);
      CHECK(feed.poll(f) == Status::kTruncated);
      CHECK(feed.exhausted());
      CHECK(feed.poll(f) == Status::kNoData);
    }
  }
  GIVEN("an empty stream") {
    StreamFileFeed feed(std::vector<std::uint8_t>{});
    kestrel::hal::Frame f{};
    THEN("it has no data") { CHECK(feed.poll(f) == Status::kNoData); }
  }
}
