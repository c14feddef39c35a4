// SPDX-License-Identifier: Apache-2.0
// FrameAssembler: frames split into random-sized chunks come out in order,
// garbage and damaged frames are skipped with the documented status and
// counter, and nothing allocates.
#include "kestrel/hal/frame_assembler.hpp"

#include <catch2/catch.hpp>
#include <cstdint>
#include <random>
#include <span>
#include <vector>

#include "frame_gen.hpp"
#include "kestrel/hal/frame_format.hpp"
#include "kestrel/hal/ring_buffer.hpp"
#include "support/alloc_guard.hpp"
#include "wire_builder.hpp"

using kestrel::Status;
using kestrel::hal::Frame;
using kestrel::hal::FrameAssembler;
using kestrel::hal::FrameKind;
namespace wire = kestrel::hal::wire;

namespace {

struct Event {
  Status status;
  Frame frame;  // meaningful for kOk and kTooManyCandidates
};

// Feed `stream` in random chunks of 1..max_chunk bytes, draining next()
// after every chunk; return every non-kNoData result.
template <std::size_t kBuf>
std::vector<Event> run(FrameAssembler<kBuf>& assembler, std::span<const std::uint8_t> stream, std::uint32_t seed,
                       std::size_t max_chunk) {
  std::mt19937 rng(seed);
  std::vector<Event> events;
  std::size_t pos = 0;
  const auto drain = [&] {
    for (;;) {
      Event e{Status::kNoData, Frame{}};
      e.status = assembler.next(e.frame);
      if (e.status == Status::kNoData) break;
      events.push_back(e);
    }
  };
  while (pos < stream.size()) {
    const std::size_t want = 1 + rng() % max_chunk;
    const std::size_t n = std::min(want, stream.size() - pos);
    const std::size_t taken = assembler.push(stream.subspan(pos, n));
    pos += taken;
    drain();
  }
  drain();
  return events;
}

std::vector<Frame> random_frames(std::uint32_t seed, std::size_t n) {
  std::mt19937 rng(seed);
  std::vector<Frame> frames;
  for (std::size_t i = 0; i < n; ++i) {
    const FrameKind kind = kestrel::test::random_kind(rng);
    frames.push_back(kestrel::test::random_frame(rng, kind, rng() % (kestrel::hal::capacity_of(kind) + 1)));
  }
  return frames;
}

void append(std::vector<std::uint8_t>& stream, const std::vector<std::uint8_t>& bytes) {
  stream.insert(stream.end(), bytes.begin(), bytes.end());
}

// Random bytes with no 'K' (the first magic byte), so they cannot hide a
// false frame start by accident; false starts are tested on purpose below.
std::vector<std::uint8_t> garbage(std::mt19937& rng, std::size_t n) {
  std::vector<std::uint8_t> g(n);
  for (auto& b : g) {
    b = static_cast<std::uint8_t>(rng());
    if (b == 0x4B) b = 0x00;
  }
  return g;
}

}  // namespace

SCENARIO("frames back to back come out in order whatever the chunking", "[hal][assembler]") {
  GIVEN("40 random frames of all kinds in one stream") {
    const auto frames = random_frames(31, 40);
    std::vector<std::uint8_t> stream;
    for (const Frame& f : frames) append(stream, kestrel::test::encode_to_vector(f));
    for (const std::size_t max_chunk : {std::size_t{1}, std::size_t{7}, std::size_t{64}, std::size_t{1500}}) {
      WHEN("it is fed in random chunks of up to " << max_chunk << " bytes") {
        FrameAssembler<> assembler;
        const auto events = run(assembler, stream, static_cast<std::uint32_t>(max_chunk), max_chunk);
        THEN("every frame comes out once, in order, equal to the input") {
          REQUIRE(events.size() == frames.size());
          for (std::size_t i = 0; i < frames.size(); ++i) {
            REQUIRE(events[i].status == Status::kOk);
            REQUIRE(kestrel::test::frames_equal(events[i].frame, frames[i]));
          }
          REQUIRE(assembler.count(Status::kOk) == frames.size());
          REQUIRE(assembler.buffered() == 0);
          REQUIRE(assembler.skipped_bytes() == 0);
        }
      }
    }
  }
}

SCENARIO("garbage before and between frames is skipped", "[hal][assembler]") {
  GIVEN("frames with random garbage before, between and after them") {
    std::mt19937 rng(77);
    const auto frames = random_frames(5, 12);
    std::vector<std::uint8_t> stream;
    std::size_t garbage_bytes = 0;
    for (const Frame& f : frames) {
      const auto g = garbage(rng, rng() % 50);
      garbage_bytes += g.size();
      append(stream, g);
      append(stream, kestrel::test::encode_to_vector(f));
    }
    const auto tail = garbage(rng, 9);
    garbage_bytes += tail.size();
    append(stream, tail);
    WHEN("it is fed in random chunks") {
      FrameAssembler<> assembler;
      const auto events = run(assembler, stream, 3, 40);
      THEN("every frame still decodes, in order, and only garbage was skipped") {
        std::vector<Frame> decoded;
        for (const Event& e : events) {
          REQUIRE((e.status == Status::kOk || e.status == Status::kBadMagic));
          if (e.status == Status::kOk) decoded.push_back(e.frame);
        }
        REQUIRE(decoded.size() == frames.size());
        for (std::size_t i = 0; i < frames.size(); ++i) REQUIRE(kestrel::test::frames_equal(decoded[i], frames[i]));
        REQUIRE(assembler.skipped_bytes() == garbage_bytes);
        REQUIRE(assembler.count(Status::kBadMagic) >= 1);
      }
    }
  }
  GIVEN("false frame starts: a partial magic, and a full magic with an impossible length") {
    const auto f1 = kestrel::test::encode_to_vector(random_frames(1, 1)[0]);
    const auto f2 = kestrel::test::encode_to_vector(random_frames(2, 1)[0]);
    std::vector<std::uint8_t> stream{0x4B, 0x53, 0x54};  // "KST" then a real frame
    append(stream, f1);
    kestrel::test::WireBuilder bogus(FrameKind::kRadar);
    bogus.payload_len = 0xFFFFFFFFu;
    const auto bogus_bytes = bogus.build();
    stream.insert(stream.end(), bogus_bytes.begin(), bogus_bytes.begin() + wire::kHeaderSize);
    append(stream, f2);
    WHEN("it is fed in one piece") {
      FrameAssembler<> assembler;
      const auto events = run(assembler, stream, 1, stream.size());
      THEN("the real frames decode around a kBadMagic and a kMalformedFrame") {
        std::vector<Status> statuses;
        for (const Event& e : events) statuses.push_back(e.status);
        REQUIRE(statuses == std::vector<Status>{Status::kBadMagic, Status::kOk, Status::kMalformedFrame,
                                                Status::kBadMagic, Status::kOk});
        REQUIRE(kestrel::test::frames_equal(events[1].frame, random_frames(1, 1)[0]));
        REQUIRE(kestrel::test::frames_equal(events[4].frame, random_frames(2, 1)[0]));
        REQUIRE(assembler.count(Status::kMalformedFrame) == 1);
        REQUIRE(assembler.skipped_bytes() == 3 + wire::kHeaderSize - 1);
      }
    }
  }
}

SCENARIO("a damaged frame is dropped whole and the next one decodes", "[hal][assembler]") {
  GIVEN("three frames, the middle one with a corrupted payload byte") {
    const auto frames = random_frames(9, 3);
    std::vector<std::uint8_t> stream;
    append(stream, kestrel::test::encode_to_vector(frames[0]));
    auto bad = kestrel::test::encode_to_vector(frames[1]);
    bad[wire::kHeaderSize + 1] = static_cast<std::uint8_t>(bad[wire::kHeaderSize + 1] ^ 0x40);
    append(stream, bad);
    append(stream, kestrel::test::encode_to_vector(frames[2]));
    WHEN("it is fed in random chunks") {
      FrameAssembler<> assembler;
      const auto events = run(assembler, stream, 4, 17);
      THEN("the statuses are kOk, kBadCrc, kOk with the outer frames intact") {
        REQUIRE(events.size() == 3);
        REQUIRE(events[0].status == Status::kOk);
        REQUIRE(events[1].status == Status::kBadCrc);
        REQUIRE(events[2].status == Status::kOk);
        REQUIRE(kestrel::test::frames_equal(events[0].frame, frames[0]));
        REQUIRE(kestrel::test::frames_equal(events[2].frame, frames[2]));
        REQUIRE(assembler.count(Status::kBadCrc) == 1);
        REQUIRE(assembler.skipped_bytes() == 0);
      }
    }
  }
  GIVEN("an over-capacity frame between two good ones") {
    std::mt19937 rng(4);
    const Frame head = kestrel::test::random_frame(rng, FrameKind::kSonar, kestrel::hal::kMaxSonarArrivals);
    const Frame extra = kestrel::test::random_frame(rng, FrameKind::kSonar, 3);
    kestrel::test::WireBuilder over(FrameKind::kSonar, head.t_us);
    over.items(head).items(extra);
    const auto frames = random_frames(10, 2);
    std::vector<std::uint8_t> stream;
    append(stream, kestrel::test::encode_to_vector(frames[0]));
    append(stream, over.build());
    append(stream, kestrel::test::encode_to_vector(frames[1]));
    THEN("it comes out as kTooManyCandidates holding its first items") {
      FrameAssembler<> assembler;
      const auto events = run(assembler, stream, 8, 100);
      REQUIRE(events.size() == 3);
      REQUIRE(events[1].status == Status::kTooManyCandidates);
      REQUIRE(kestrel::test::frames_equal(events[1].frame, head));
      REQUIRE(events[2].status == Status::kOk);
      REQUIRE(kestrel::test::frames_equal(events[2].frame, frames[1]));
    }
  }
}

SCENARIO("the assembler drains a UART-style ring buffer", "[hal][assembler][ring]") {
  GIVEN("a 64-byte ring that an ISR fills with a stream of frames") {
    kestrel::hal::ByteRingBuffer<64> ring;
    const auto frames = random_frames(12, 10);
    std::vector<std::uint8_t> stream;
    for (const Frame& f : frames) append(stream, kestrel::test::encode_to_vector(f));
    WHEN("the main loop pulls and decodes between ISR bursts") {
      FrameAssembler<> assembler;
      std::vector<Frame> decoded;
      std::size_t pos = 0;
      std::mt19937 rng(6);
      while (pos < stream.size() || assembler.buffered() > 0) {
        const std::size_t burst = std::min<std::size_t>(1 + rng() % 64, stream.size() - pos);
        pos += ring.push(std::span<const std::uint8_t>(stream).subspan(pos, burst));
        assembler.pull(ring);
        Frame f;
        Status s;
        while ((s = assembler.next(f)) != Status::kNoData) {
          REQUIRE(s == Status::kOk);
          decoded.push_back(f);
        }
        if (pos == stream.size() && ring.empty()) break;
      }
      THEN("every frame arrives, none overflowed") {
        REQUIRE(ring.overflow_count() == 0);
        REQUIRE(decoded.size() == frames.size());
        for (std::size_t i = 0; i < frames.size(); ++i) REQUIRE(kestrel::test::frames_equal(decoded[i], frames[i]));
      }
    }
  }
}

SCENARIO("the assembler makes progress when pushed more than it holds", "[hal][assembler]") {
  GIVEN("a stream of maximum-size frames longer than the buffer, pushed as one span") {
    std::mt19937 rng(13);
    std::vector<Frame> frames;
    std::vector<std::uint8_t> stream;
    for (int i = 0; i < 12; ++i) {
      frames.push_back(kestrel::test::random_frame(rng, FrameKind::kPcl, kestrel::hal::kMaxPclCandidates));
      append(stream, kestrel::test::encode_to_vector(frames.back()));
    }
    REQUIRE(stream.size() > wire::kMaxFrameBytes);
    THEN("push takes what fits, and alternating push and next consumes it all") {
      FrameAssembler<> assembler;
      std::span<const std::uint8_t> rest(stream);
      std::size_t decoded = 0;
      int rounds = 0;
      while (!rest.empty() && rounds++ < 1000) {
        const std::size_t n = assembler.push(rest);
        REQUIRE(n > 0);
        rest = rest.subspan(n);
        Frame f;
        Status s;
        while ((s = assembler.next(f)) != Status::kNoData) {
          REQUIRE(s == Status::kOk);
          REQUIRE(kestrel::test::frames_equal(f, frames[decoded]));
          ++decoded;
        }
      }
      REQUIRE(decoded == frames.size());
    }
  }
}

SCENARIO("the assembler does not allocate", "[hal][assembler][alloc]") {
  GIVEN("a stream with good frames, garbage and a bad CRC, prepared in advance") {
    const auto frames = random_frames(21, 6);
    std::vector<std::uint8_t> stream;
    for (const Frame& f : frames) append(stream, kestrel::test::encode_to_vector(f));
    stream.insert(stream.begin() + 10, {1, 2, 3, 0x4B});
    auto* assembler = new FrameAssembler<>();  // allocated outside the guard
    WHEN("it is pushed and drained under an allocation guard") {
      std::size_t allocations = 1;
      std::size_t results = 0;
      {
        kestrel::test::AllocationGuard guard;
        std::span<const std::uint8_t> rest(stream);
        for (int round = 0; round < 1000 && !rest.empty(); ++round) {
          rest = rest.subspan(assembler->push(rest.first(std::min<std::size_t>(rest.size(), 37))));
          Frame f;
          while (assembler->next(f) != Status::kNoData) ++results;
        }
        allocations = guard.allocations();
      }
      THEN("nothing was allocated") {
        REQUIRE(results > 0);
        REQUIRE(allocations == 0);
      }
    }
    delete assembler;
  }
}
