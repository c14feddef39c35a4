// SPDX-License-Identifier: Apache-2.0
// ByteRingBuffer: FIFO order, wrap-around, overflow accounting, peek/drop,
// and a producer/consumer thread pair checking the acquire/release protocol
// on the host (run it under TSan to check the ordering itself).
#include "kestrel/hal/ring_buffer.hpp"

#include <array>
#include <catch2/catch.hpp>
#include <cstdint>
#include <deque>
#include <random>
#include <thread>
#include <vector>

using kestrel::hal::ByteRingBuffer;

SCENARIO("a byte ring is a bounded FIFO", "[hal][ring]") {
  GIVEN("an empty ring of 8 bytes") {
    ByteRingBuffer<8> ring;
    STATIC_REQUIRE(ByteRingBuffer<8>::capacity() == 8);
    REQUIRE(ring.empty());
    WHEN("5 bytes are pushed") {
      for (std::uint8_t b = 1; b <= 5; ++b) REQUIRE(ring.push(b));
      THEN("size is 5 and they pop in order") {
        REQUIRE(ring.size() == 5);
        std::array<std::uint8_t, 8> out{};
        REQUIRE(ring.pop(out) == 5);
        REQUIRE(out[0] == 1);
        REQUIRE(out[4] == 5);
        REQUIRE(ring.empty());
      }
      THEN("peek copies without removing and drop removes without copying") {
        std::array<std::uint8_t, 3> out{};
        REQUIRE(ring.peek(out) == 3);
        REQUIRE(out == std::array<std::uint8_t, 3>{1, 2, 3});
        REQUIRE(ring.size() == 5);
        REQUIRE(ring.drop(2) == 2);
        std::uint8_t b = 0;
        REQUIRE(ring.pop(b));
        REQUIRE(b == 3);
        REQUIRE(ring.drop(100) == 2);
        REQUIRE(ring.empty());
        REQUIRE_FALSE(ring.pop(b));
        REQUIRE(b == 3);
      }
    }
    WHEN("it is filled to capacity and pushed once more") {
      for (std::uint8_t b = 0; b < 8; ++b) REQUIRE(ring.push(b));
      THEN("the extra push fails, is counted, and the stored bytes are intact") {
        REQUIRE(ring.size() == 8);
        REQUIRE_FALSE(ring.push(99));
        REQUIRE_FALSE(ring.push(100));
        REQUIRE(ring.overflow_count() == 2);
        std::array<std::uint8_t, 8> out{};
        REQUIRE(ring.pop(out) == 8);
        REQUIRE(out == std::array<std::uint8_t, 8>{0, 1, 2, 3, 4, 5, 6, 7});
      }
    }
    WHEN("a span larger than the free space is pushed") {
      REQUIRE(ring.push(std::uint8_t{42}));
      const std::array<std::uint8_t, 10> in{0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
      THEN("the bytes that fit are stored and each lost byte is an overflow") {
        REQUIRE(ring.push(in) == 7);
        REQUIRE(ring.overflow_count() == 3);
        std::array<std::uint8_t, 8> out{};
        REQUIRE(ring.pop(out) == 8);
        REQUIRE(out == std::array<std::uint8_t, 8>{42, 0, 1, 2, 3, 4, 5, 6});
      }
    }
  }
}

SCENARIO("a byte ring wraps around indefinitely", "[hal][ring]") {
  GIVEN("a ring of 16 bytes and a std::deque model") {
    ByteRingBuffer<16> ring;
    std::deque<std::uint8_t> model;
    std::mt19937 rng(2024);
    std::uint32_t expected_overflows = 0;
    WHEN("random pushes and pops run for many times the capacity") {
      std::uint8_t next = 0;
      for (int step = 0; step < 20000; ++step) {
        if (rng() % 2 == 0) {
          const std::size_t n = rng() % 7;
          std::vector<std::uint8_t> in(n);
          for (auto& b : in) b = next++;
          const std::size_t stored = ring.push(in);
          const std::size_t room = 16 - model.size();
          REQUIRE(stored == std::min(n, room));
          expected_overflows += static_cast<std::uint32_t>(n - stored);
          model.insert(model.end(), in.begin(), in.begin() + static_cast<std::ptrdiff_t>(stored));
        } else {
          std::array<std::uint8_t, 6> out{};
          const std::size_t want = rng() % 7;
          const std::size_t got = ring.pop(std::span<std::uint8_t>(out).first(want));
          REQUIRE(got == std::min(want, model.size()));
          for (std::size_t i = 0; i < got; ++i) {
            REQUIRE(out[i] == model.front());
            model.pop_front();
          }
        }
        REQUIRE(ring.size() == model.size());
      }
      THEN("it matched the model throughout and counted every lost byte") {
        REQUIRE(ring.overflow_count() == expected_overflows);
      }
    }
  }
}

SCENARIO("a producer thread and a consumer thread pass bytes in order", "[hal][ring]") {
  GIVEN("a 64-byte ring shared by two threads") {
    ByteRingBuffer<64> ring;
    constexpr std::size_t kBytes = 200000;
    WHEN("the producer pushes a counting sequence, retrying when full") {
      std::thread producer([&ring] {
        // Yield when full (and the consumer when empty): on a loaded 2-core
        // machine a spinning thread can hold the core its peer needs for
        // a whole time slice; yielding keeps the interleaving and frees it.
        for (std::size_t i = 0; i < kBytes;) {
          if (ring.size() < ring.capacity() && ring.push(static_cast<std::uint8_t>(i * 7))) {
            ++i;
          } else {
            std::this_thread::yield();
          }
        }
      });
      std::vector<std::uint8_t> received;
      received.reserve(kBytes);
      std::array<std::uint8_t, 13> chunk{};
      while (received.size() < kBytes) {
        const std::size_t n = ring.pop(chunk);
        if (n == 0) std::this_thread::yield();
        received.insert(received.end(), chunk.begin(), chunk.begin() + static_cast<std::ptrdiff_t>(n));
      }
      producer.join();
      THEN("the consumer sees every byte once, in order, with no overflow") {
        REQUIRE(ring.overflow_count() == 0);
        bool in_order = true;
        for (std::size_t i = 0; i < kBytes; ++i) in_order = in_order && received[i] == static_cast<std::uint8_t>(i * 7);
        REQUIRE(in_order);
      }
    }
  }
}
