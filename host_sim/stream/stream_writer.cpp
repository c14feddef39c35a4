// SPDX-License-Identifier: Apache-2.0
#include "stream/stream_writer.hpp"

#include <array>
#include <fstream>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>

#include "kestrel/hal/frame_codec.hpp"
#include "kestrel/hal/frame_format.hpp"
#include "kestrel/host/stream_file_feed.hpp"
#include "stream/quantise.hpp"

namespace kestrel::sim {

std::vector<std::uint8_t> encode_stream(const std::vector<MeasurementFrame>& frames) {
  std::vector<std::uint8_t> bytes;
  std::array<std::uint8_t, hal::wire::kMaxEncodedFrameBytes> buffer{};
  for (const MeasurementFrame& f : frames) {
    const hal::Frame wire = to_wire_frame(f);
    std::size_t written = 0;
    const Status s = hal::encode(wire, buffer, written);
    if (s != Status::kOk) {
      throw std::runtime_error("cannot encode frame at t = " + std::to_string(f.t_s) + " s: " + to_string(s));
    }
    bytes.insert(bytes.end(), buffer.begin(), buffer.begin() + static_cast<std::ptrdiff_t>(written));
  }
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
  std::vector<MeasurementFrame> frames;
  skipped = 0;
  hal::Frame frame{};
  for (;;) {
    const Status s = feed.poll(frame);
    if (s == Status::kNoData) break;
    if (s == Status::kOk || s == Status::kTooManyCandidates) {
      frames.push_back(from_wire_frame(frame));
    } else {
      // Keep the place of the damaged frame so indices match the Runner's
      // frame count; the placeholder has no time and no plots.
      MeasurementFrame placeholder;
      placeholder.t_s = std::numeric_limits<double>::quiet_NaN();
      frames.push_back(placeholder);
      ++skipped;
    }
  }
  return frames;
}

}  // namespace kestrel::sim
