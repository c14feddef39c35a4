// SPDX-License-Identifier: Apache-2.0
// StreamFileFeed: decode frames one by one out of an in-memory stream.
#include "kestrel/host/stream_file_feed.hpp"

#include <fstream>
#include <iterator>
#include <span>
#include <stdexcept>
#include <utility>

#include "kestrel/hal/frame_codec.hpp"
#include "kestrel/hal/frame_format.hpp"

namespace kestrel::host {

StreamFileFeed::StreamFileFeed(std::vector<std::uint8_t> bytes) : bytes_(std::move(bytes)) {}

StreamFileFeed StreamFileFeed::open(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open stream file '" + path.string() + "'");
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw std::runtime_error("cannot read stream file '" + path.string() + "'");
  return StreamFileFeed(std::move(bytes));
}

std::size_t StreamFileFeed::next_magic_after(std::size_t from) const {
  for (std::size_t i = from; i + 4 <= bytes_.size(); ++i) {
    if (hal::wire::load_u32(std::span<const std::uint8_t>(bytes_), i) == hal::wire::kMagic) return i;
  }
  return bytes_.size();
}

Status StreamFileFeed::poll(hal::Frame& frame) {
  if (exhausted()) return Status::kNoData;
  const std::span<const std::uint8_t> rest(bytes_.data() + offset_, bytes_.size() - offset_);
  std::size_t consumed = 0;
  const Status status = hal::decode(rest, frame, consumed);
  switch (status) {
    case Status::kTruncated:
      // The file is complete: these bytes will never become a frame.
      offset_ = bytes_.size();
      break;
    case Status::kBadMagic:
    case Status::kMalformedFrame:
      // consumed == 1 means "resynchronise": skip to the next magic at once.
      offset_ = consumed == 1 ? next_magic_after(offset_ + 1) : offset_ + consumed;
      break;
    default:
      // A decoder that consumed nothing would stall the feed: resynchronise.
      offset_ = consumed == 0 ? next_magic_after(offset_ + 1) : offset_ + consumed;
      break;
  }
  return status;
}

}  // namespace kestrel::host
