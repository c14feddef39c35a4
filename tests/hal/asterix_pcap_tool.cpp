// SPDX-License-Identifier: Apache-2.0
// Host tool for the tshark check (asterix_tshark_check.py): writes a CAT048
// block and a CAT062 block, each as one UDP datagram (port 8600) in its own
// pcap file, and expected.json with what Kestrel made of them: the frames
// the CAT048 reader decoded and the track reports the CAT062 writer wrote.
// Wireshark then judges both independently.
// Usage: kestrel_asterix_pcap <output dir>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "asterix_builder.hpp"
#include "kestrel/hal/asterix_cat048.hpp"
#include "kestrel/hal/asterix_cat062.hpp"
#include "kestrel/tracking/radar_tracker.hpp"

namespace {

using kestrel::Status;
using kestrel::test::Bytes;
namespace ax = kestrel::hal::asterix;
constexpr std::uint16_t kPort = 8600;

void le(Bytes& b, std::uint32_t v, int n) {
  for (int i = 0; i < n; ++i) b.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

// pcap (microsecond, little-endian) with LINKTYPE_RAW: IPv4 + UDP + payload.
Bytes pcap(const Bytes& payload) {
  Bytes f;
  le(f, 0xA1B2C3D4u, 4);
  le(f, 2, 2);
  le(f, 4, 2);
  le(f, 0, 4);
  le(f, 0, 4);
  le(f, 65535, 4);
  le(f, 101, 4);  // LINKTYPE_RAW
  Bytes ip{0x45, 0x00};
  kestrel::test::put_be(ip, static_cast<std::uint32_t>(20 + 8 + payload.size()), 2);
  ip.insert(ip.end(), {0x00, 0x01, 0x40, 0x00, 64, 17, 0, 0, 10, 0, 0, 1, 10, 0, 0, 2});
  std::uint32_t sum = 0;
  for (std::size_t i = 0; i < 20; i += 2) sum += static_cast<std::uint32_t>((ip[i] << 8) | ip[i + 1]);
  while (sum > 0xFFFFu) sum = (sum & 0xFFFFu) + (sum >> 16);
  ip[10] = static_cast<std::uint8_t>(~sum >> 8);
  ip[11] = static_cast<std::uint8_t>(~sum);
  kestrel::test::put_be(ip, kPort, 2);
  kestrel::test::put_be(ip, kPort, 2);
  kestrel::test::put_be(ip, static_cast<std::uint32_t>(8 + payload.size()), 2);
  kestrel::test::put_be(ip, 0, 2);  // no UDP checksum (allowed on IPv4)
  ip.insert(ip.end(), payload.begin(), payload.end());
  le(f, 1'700'000'000u, 4);
  le(f, 0, 4);
  le(f, static_cast<std::uint32_t>(ip.size()), 4);
  le(f, static_cast<std::uint32_t>(ip.size()), 4);
  f.insert(f.end(), ip.begin(), ip.end());
  return f;
}

bool write(const std::string& path, const Bytes& b) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
  return static_cast<bool>(out);
}

kestrel::test::Cat048PlotSpec plot(std::uint32_t tod, std::uint16_t rho, std::uint16_t theta, std::uint16_t track,
                                   int doppler) {
  kestrel::test::Cat048PlotSpec p;
  p.sac = 25;
  p.sic = 201;
  p.tod_128 = tod;
  p.rho_256nm = rho;
  p.theta = theta;
  p.with_track_number = true;
  p.track_number = track;
  p.with_doppler = true;
  p.doppler_mps = static_cast<std::int16_t>(doppler);
  return p;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s <output dir>\n", argv[0]);
    return 2;
  }
  const std::string dir = argv[1];
  std::string json;

  // CAT048: the four cardinal azimuths and an odd one, two times of day.
  const std::vector<kestrel::test::Cat048PlotSpec> written048{
      plot(5'529'664, 2560, 0x0000, 1, -5), plot(5'529'664, 1280, 0x4000, 2, 0),
      plot(5'529'664, 12'345, 0x8000, 3, 100), plot(5'529'792, 65'535, 0xC000, 4, -512),
      plot(5'529'792, 1, 0x1234, 4095, 511)};
  const Bytes block048 = kestrel::test::cat048_block(written048);
  std::string written = "  \"cat048_written\": [";
  for (std::size_t k = 0; k < written048.size(); ++k) {
    const auto& p = written048[k];
    char line[200];
    std::snprintf(line, sizeof line,
                  "%s\n    {\"sac\": %u, \"sic\": %u, \"track_number\": %u, \"doppler_mps\": %d}",
                  k == 0 ? "" : ",", static_cast<unsigned>(p.sac), static_cast<unsigned>(p.sic),
                  static_cast<unsigned>(p.track_number), static_cast<int>(p.doppler_mps));
    written += line;
  }
  json = "{\n" + written + "\n  ],\n  \"cat048\": [";
  ax::Cat048Reader reader;
  std::size_t len = 0;
  if (reader.open(block048, len) != Status::kOk) return 1;
  bool first = true;
  for (int i = 0; i < 10; ++i) {
    kestrel::hal::Frame f{};
    const Status s = reader.next(f);
    if (s == Status::kNoData) break;
    if (s != Status::kOk) return 1;
    for (std::size_t k = 0; k < f.count; ++k) {
      const kestrel::hal::RadarPlot& p = f.radar[k];
      char line[256];
      std::snprintf(line, sizeof line,
                    "%s\n    {\"t_us\": %lld, \"range_mm\": %u, \"bearing_bam\": %d, \"range_rate_mmps\": %d, "
                    "\"sensor_id\": %u}",
                    first ? "" : ",", static_cast<long long>(f.t_us), p.range_mm, p.bearing_bam, p.range_rate_mmps,
                    static_cast<unsigned>(p.sensor_id));
      json += line;
      first = false;
    }
  }
  json += "\n  ],\n  \"cat062\": [";

  // CAT062: three reports of the EKF-CA radar tracker.
  using Report = kestrel::TrackReport<kestrel::EkfCa<double>>;
  using Layout = kestrel::CaMotion<double>::Layout;
  struct Spec {
    std::uint32_t id;
    double x, y, vx, vy, sx, sy;
    bool confirmed;
  };
  const Spec specs[] = {{17, 12'345.5, -6'789.0, 150.25, -75.5, 12.5, 30.0, true},
                        {4242, -250'000.0, 310'000.5, -8'000.0, 8'191.75, 0.5, 32'767.5, false},
                        {65'535, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, true}};
  std::vector<ax::Cat062Track> tracks;
  first = true;
  for (const Spec& s : specs) {
    Report r;
    r.t_us = 43'200'500'000;
    r.track_id = s.id;
    r.status = s.confirmed ? kestrel::TrackStatus::kConfirmed : kestrel::TrackStatus::kTentative;
    r.x.setZero();
    r.x(Layout::kX) = s.x;
    r.x(Layout::kY) = s.y;
    r.x(Layout::kVx) = s.vx;
    r.x(Layout::kVy) = s.vy;
    r.P.setIdentity();
    r.P(Layout::kX, Layout::kX) = s.sx * s.sx;
    r.P(Layout::kY, Layout::kY) = s.sy * s.sy;
    ax::Cat062Track t;
    if (ax::to_cat062(r, t) != Status::kOk) return 1;
    tracks.push_back(t);
    char line[320];
    std::snprintf(line, sizeof line,
                  "%s\n    {\"t_us\": %lld, \"track_id\": %u, \"x_m\": %.17g, \"y_m\": %.17g, \"vx_mps\": %.17g, "
                  "\"vy_mps\": %.17g, \"sigma_x_m\": %.17g, \"sigma_y_m\": %.17g, \"tentative\": %s}",
                  first ? "" : ",", static_cast<long long>(r.t_us), s.id, s.x, s.y, s.vx, s.vy, s.sx, s.sy,
                  s.confirmed ? "false" : "true");
    json += line;
    first = false;
  }
  ax::Cat062Source src;
  src.sac = 25;
  src.sic = 100;
  src.has_service_id = true;
  src.service_id = 3;
  Bytes block062(4096);
  std::size_t size062 = 0;
  if (ax::encode_cat062(src, tracks, block062, size062) != Status::kOk) return 1;
  block062.resize(size062);
  json += "\n  ],\n  \"cat062_source\": {\"sac\": 25, \"sic\": 100, \"service_id\": 3}\n}\n";

  std::ofstream(dir + "/expected.json") << json;
  if (!write(dir + "/cat048.pcap", pcap(block048)) || !write(dir + "/cat062.pcap", pcap(block062))) return 1;
  return 0;
}
