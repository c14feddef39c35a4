// SPDX-License-Identifier: Apache-2.0
// AsterixFileFeed: CAT048 blocks of an in-memory recording, frame by frame.
#include "kestrel/host/asterix_file_feed.hpp"

#include <fstream>
#include <iterator>
#include <span>
#include <stdexcept>
#include <utility>

namespace kestrel::host {

AsterixFileFeed::AsterixFileFeed(std::vector<std::uint8_t> bytes) : bytes_(std::move(bytes)) {}

AsterixFileFeed AsterixFileFeed::open(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open ASTERIX file '" + path.string() + "'");
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw std::runtime_error("cannot read ASTERIX file '" + path.string() + "'");
  return AsterixFileFeed(std::move(bytes));
}

Status AsterixFileFeed::poll(hal::Frame& frame) {
  // Each pass either returns or opens a block (offset_ strictly grows, by at
  // least 3 bytes), so the loop ends within size / 3 + 1 passes.
  for (std::size_t pass = 0; pass <= bytes_.size() / hal::asterix::kBlockHeaderSize + 1; ++pass) {
    if (block_open_) {
      const Status s = reader_.next(frame);
      if (s == Status::kOk || s == Status::kTooManyCandidates) {
        ++counters_.frames;
        return s;
      }
      block_open_ = false;
      if (s == Status::kMalformedFrame) {
        ++counters_.malformed;
        return s;
      }
      continue;  // kNoData: the block is done
    }
    if (offset_ >= bytes_.size()) return Status::kNoData;
    const std::span<const std::uint8_t> rest(bytes_.data() + offset_, bytes_.size() - offset_);
    std::size_t block_len = 0;
    const Status opened = reader_.open(rest, block_len);
    switch (opened) {
      case Status::kOk:
        ++counters_.blocks;
        block_open_ = true;
        offset_ += block_len;
        break;
      case Status::kUnknownKind:
        ++counters_.unknown_category;
        offset_ += block_len;
        return opened;
      case Status::kTruncated:
        ++counters_.truncated;
        offset_ = bytes_.size();
        return opened;
      default:  // kMalformedFrame: LEN < 3, no later block can be found
        ++counters_.malformed;
        offset_ = bytes_.size();
        return opened;
    }
  }
  return Status::kNoData;
}

}  // namespace kestrel::host
