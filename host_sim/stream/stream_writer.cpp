// SPDX-License-Identifier: Apache-2.0
#include "stream/stream_writer.hpp"

#include <array>
#include <fstream>
#include <span>
#include <stdexcept>
#include <string>

#include "kestrel/hal/frame_codec.hpp"
#include "kestrel/hal/frame_format.hpp"
#include "kestrel/host/stream_file_feed.hpp"
#include "stream/feed_frames.hpp"
#include "stream/quantise.hpp"

namespace kestrel::sim {

void append_encoded(const hal::Frame& wire, std::vector<std::uint8_t>& bytes) {
  std::array<std::uint8_t, hal::wire::kMaxEncodedFrameBytes> buffer;
  std::size_t written = 0;
  const Status s = hal::encode(wire, buffer, written);
  if (s != Status::kOk) {
    throw std::runtime_error("cannot encode the frame at t = " + std::to_string(static_cast<double>(wire.t_us) * 1e-6) +
                             " s: " + to_string(s));
  }
  bytes.insert(bytes.end(), buffer.begin(), buffer.begin() + static_cast<std::ptrdiff_t>(written));
}

std::vector<std::uint8_t> encode_stream(const std::vector<MeasurementFrame>& frames) {
  std::vector<std::uint8_t> bytes;
  for (const MeasurementFrame& f : frames) append_encoded(to_wire_frame(f), bytes);
  return bytes;
}

void write_bytes(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error("cannot create '" + path.string() + "'");
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error("cannot write '" + path.string() + "'");
}

std::vector<MeasurementFrame> decode_stream(const std::vector<std::uint8_t>& bytes, std::size_t& skipped) {
  host::StreamFileFeed feed(bytes);
  return frames_of_feed(feed, skipped);
}

}  // namespace kestrel::sim
