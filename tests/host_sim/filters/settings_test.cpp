// SPDX-License-Identifier: Apache-2.0
// Parameters by key (filters/settings.hpp): --set and --config reach the
// tracker each filter builds, a bad key or value is refused naming it and
// changes nothing, and every key is documented in docs/parameters.md.
#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "filters/ekf_ca.hpp"
#include "filters/ekf_ca_rr.hpp"
#include "filters/imm_filters.hpp"
#include "filters/settings.hpp"

using namespace kestrel;       // NOLINT(google-build-using-namespace)
using namespace kestrel::sim;  // NOLINT(google-build-using-namespace)

namespace {
FilterOptions with(const std::vector<std::string>& sets) {
  std::vector<Setting> settings;
  for (const std::string& s : sets) settings.push_back(parse_setting(s, "--set"));
  FilterOptions o;
  apply_settings(settings, o);
  return o;
}

std::string refusal(const std::vector<std::string>& sets, FilterOptions& o) {
  try {
    std::vector<Setting> settings;
    for (const std::string& s : sets) settings.push_back(parse_setting(s, "--set"));
    apply_settings(settings, o);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

std::filesystem::path write_file(const std::string& name, const std::string& text) {
  const std::filesystem::path p = std::filesystem::temp_directory_path() / name;
  std::ofstream(p) << text;
  return p;
}
}  // namespace

SCENARIO("KEY=VALUE parses to a finite number or a boolean, anything else is refused", "[settings]") {
  const Setting s = parse_setting("qj=160", "--set");
  CHECK(s.key == "qj");
  CHECK(s.value == 160.0);
  CHECK(s.origin == "--set");
  CHECK(parse_setting("board_gate=true", "--set").value == 1.0);
  CHECK(parse_setting("board_gate=false", "--set").value == 0.0);
  for (const char* bad : {"qj", "=5", "qj=", "qj=abc", "qj=1.6x", "qj=nan", "qj=inf"}) {
    INFO(bad);
    CHECK_THROWS_AS(parse_setting(bad, "--set"), std::invalid_argument);
  }
}

SCENARIO("Settings reach the radar tracker each filter builds, and its summary", "[settings]") {
  const FilterOptions o = with({"qj=16", "confirm_m=3", "confirm_n=5", "max_coast_misses=7",
                                "gate_probability=0.95", "max_predict_us=4000000", "sigma_range_m=10"});
  REQUIRE(o.qj.has_value());
  const RadarTrackerParams p = radar_tracker_params(o);
  CHECK(p.qj == 16.0);
  CHECK(p.sigma_range_m == 10.0);
  CHECK(p.sigma_bearing_rad == RadarTrackerParams{}.sigma_bearing_rad);

  const auto ekf = make_ekf_ca_tracker<float>(o);
  CHECK(ekf.config().confirm_m == 3);
  CHECK(ekf.config().confirm_n == 5);
  CHECK(ekf.config().max_coast_misses == 7);
  CHECK(ekf.config().gate_tentative == GateProbability::k95);
  CHECK(ekf.config().max_predict_us == 4'000'000);

  const auto imm = make_imm_tracker<double>(o);
  CHECK(imm.config().confirm_m == 3);
  CHECK(imm.config().gate_tentative == GateProbability::k95);
  CHECK(imm_params(o).sigma_range_m == 10.0);
  CHECK(imm_params(o).ca_qj == 16.0);

  for (const char* name : {"ekf-ca", "r2aekf", "ukf", "imm-f32"}) {
    INFO(name);
    const FilterSetup s = find_filter(name).setup(o);
    CHECK(s.parameters.at("confirm_m") == 3.0);
    CHECK(s.parameters.at("max_coast_misses") == 7.0);
    CHECK(s.parameters.at("gate_probability") == 0.95);
    CHECK(s.parameters.at("sigma_range_m") == 10.0);
  }
}

SCENARIO("The adaptive noise keys reach the trackers built with it and are refused by the others", "[settings]") {
  const FilterOptions o = with({"robust_noise_gain=0.2", "robust_noise_max_scale=9", "robust_gate_factor=25",
                                "board_gate=true"});
  GIVEN("EKF-CA and the IMM, which kestrel-sim builds with AdaptiveMeasurementNoise") {
    THEN("they take the rule") {
      const auto ekf = make_ekf_ca_tracker<float>(o);
      CHECK(ekf.measurement_noise().enabled());
      CHECK(ekf.measurement_noise().rule().gain == 0.2f);
      CHECK(ekf.measurement_noise().rule().max_scale == 9.0f);
      const auto imm = make_imm_tracker<double>(o);
      CHECK(imm.measurement_noise().enabled());
      CHECK(!make_imm_tracker<double>(FilterOptions{}).measurement_noise().enabled());
    }
  }
  GIVEN("EKF-CA-RR, built without it") {
    THEN("a gain is refused naming the key; a gain of 0 is not") {
      try {
        (void)make_ekf_ca_rr_tracker<double>(o);
        FAIL("no refusal");
      } catch (const std::invalid_argument& e) {
        CHECK(std::string(e.what()).find("robust_noise_gain") != std::string::npos);
        CHECK(std::string(e.what()).find("without the adaptive measurement noise") != std::string::npos);
      }
      CHECK_NOTHROW(make_ekf_ca_rr_tracker<double>(with({"robust_noise_gain=0", "robust_gate_factor=25"})));
    }
  }
}

SCENARIO("The seed keys reach the trackers built with the second hypotheses and are refused by the others",
         "[settings]") {
  const FilterOptions o = with({"seed_extra_frames=1", "seed_from_pairs=true"});
  GIVEN("EKF-CA and the IMM, which kestrel-sim builds with TwoPointHypothesesInitiator") {
    THEN("their initiators take the rules; by default the rules are off") {
      const auto ekf = make_ekf_ca_tracker<float>(o);
      CHECK(ekf.initiator().seed_extra_frames == 1);
      CHECK(ekf.initiator().seed_from_pairs);
      const auto imm = make_imm_tracker<double>(o);
      CHECK(imm.initiator().seed_extra_frames == 1);
      CHECK(imm.initiator().seed_from_pairs);
      const auto plain = make_ekf_ca_tracker<double>(FilterOptions{});
      CHECK(plain.initiator().seed_extra_frames == 0);
      CHECK(!plain.initiator().seed_from_pairs);
    }
  }
  GIVEN("EKF-CA-RR, built with TwoPointInitiator") {
    THEN("either rule is refused naming the keys; their defaults are not") {
      for (const char* key : {"seed_extra_frames=1", "seed_from_pairs=1"}) {
        try {
          (void)make_ekf_ca_rr_tracker<double>(with({key}));
          FAIL("no refusal of " << key);
        } catch (const std::invalid_argument& e) {
          CHECK(std::string(e.what()).find("seed_extra_frames") != std::string::npos);
          CHECK(std::string(e.what()).find("one hypothesis per start") != std::string::npos);
        }
      }
      CHECK_NOTHROW(make_ekf_ca_rr_tracker<double>(with({"seed_extra_frames=0", "seed_from_pairs=0"})));
    }
  }
}

SCENARIO("Gate and IMM keys set the options their own flags set", "[settings]") {
  const FilterOptions o = with({"gate_d2=13.8", "board_gate=true", "robust_gate_factor=25", "imm.p_stay=0.9"});
  REQUIRE(o.confirmed_gate_d2.has_value());
  CHECK(*o.confirmed_gate_d2 == 13.8);
  CHECK(o.board_gate);
  REQUIRE(o.robust_gate_factor.has_value());
  CHECK(*o.robust_gate_factor == 25.0);
  REQUIRE(o.imm.size() == 1);
  CHECK(imm_params(o).switching[1][1] == 0.9);
}

SCENARIO("A later setting wins over an earlier one", "[settings]") {
  CHECK(radar_tracker_params(with({"confirm_n=4", "confirm_n=6"})).confirm_n == 6);
}

SCENARIO("An unknown key or a value out of range is refused by name and changes nothing", "[settings]") {
  FilterOptions o = with({"confirm_m=3"});
  const std::vector<std::vector<std::string>> bad = {
      {"bogus=1"},           {"confirm_n=9"},           {"confirm_m=0"},         {"confirm_m=2.5"},
      {"confirm_m=4", "confirm_n=3"}, {"gate_probability=0.97"}, {"robust_gate_factor=0.5"},
      {"max_coast_misses=-1"}, {"qj=0"},                {"sigma_range_m=-3"},     {"board_gate=2"},
      {"resync_frames=256"}, {"max_forward_jump_us=0"}, {"imm.=1"}, {"seed_from_pairs=2"},
      {"robust_noise_max_scale=0.5"}, {"robust_noise_gain=1.5"},
  };
  // The radar keys' ranges read as the PCL and sonar keys' do.
  CHECK_THAT(refusal({"robust_noise_max_scale=0.5"}, o), Catch::Contains("=0.5: out of range (>= 1)"));
  CHECK_THAT(refusal({"seed_from_pairs=2"}, o), Catch::Contains("=2: out of range (false or true)"));
  CHECK_THAT(refusal({"confirm_n=9"}, o), Catch::Contains("=9: out of range (whole, 1..8)"));
  CHECK_THAT(refusal({"gate_probability=0.97"}, o), Catch::Contains("out of range (0.9, 0.95, 0.99, 0.995, 0.999)"));
  CHECK_THAT(refusal({"max_forward_jump_us=0"}, o), Catch::Contains("out of range (whole, > 0, <= 9007199254740992)"));
  CHECK_THAT(refusal({"bogus=1"}, o), Catch::EndsWith("`kestrel-sim list --settings`"));
  CHECK_THAT(refusal({"bogus=1"}, o), !Catch::Contains("it is a key of"));
  CHECK_THAT(refusal({"sigma_rb_m=2"}, o),
             Catch::Contains("unknown key of the radar tracker (known: qj,") &&
                 Catch::Contains("); it is a key of the PCL tracker. The keys of each tracker"));
  for (const auto& sets : bad) {
    INFO(sets.front());
    const std::string why = refusal(sets, o);
    CHECK_FALSE(why.empty());
    CHECK(why.find(sets.back().substr(0, sets.back().find('='))) != std::string::npos);
    CHECK(radar_tracker_params(o).confirm_m == 3);
    CHECK(o.radar.size() == 1);
    CHECK_FALSE(o.qj.has_value());
    CHECK_FALSE(o.board_gate);
  }
}

SCENARIO("A config file is a JSON object of numbers and booleans, nested objects joined with dots", "[settings]") {
  const auto good = write_file("kestrel_settings_good.json",
                               R"({"qj": 160, "confirm_m": 3, "board_gate": true, "imm": {"p_stay": 0.9}})");
  const std::vector<Setting> s = read_config_file(good.string());
  REQUIRE(s.size() == 4);
  FilterOptions o;
  apply_settings(s, o);
  CHECK(*o.qj == 160.0);
  CHECK(radar_tracker_params(o).confirm_m == 3);
  CHECK(o.board_gate);
  REQUIRE(o.imm.size() == 1);
  CHECK(o.imm.front().rfind("p_stay=0.9", 0) == 0);

  const auto text = write_file("kestrel_settings_text.json", R"({"qj": "160"})");
  CHECK_THROWS_AS(read_config_file(text.string()), std::invalid_argument);
  const auto list = write_file("kestrel_settings_list.json", R"([1, 2])");
  CHECK_THROWS_AS(read_config_file(list.string()), std::invalid_argument);
  const auto broken = write_file("kestrel_settings_broken.json", R"({"qj": 160)");
  CHECK_THROWS_AS(read_config_file(broken.string()), std::runtime_error);
  CHECK_THROWS_AS(read_config_file("/nonexistent/kestrel.json"), std::runtime_error);
}

SCENARIO("Every key takes its own default, and docs/parameters.md gives each key with it", "[settings]") {
  std::ifstream in(KESTREL_DOCS_DIR "/parameters.md");
  REQUIRE(in);
  std::stringstream doc;
  doc << in.rdbuf();
  for (const SettingInfo& i : setting_table()) {
    INFO(i.key);
    CHECK(doc.str().find("| `" + i.key + "` | " + i.default_text + " |") != std::string::npos);
    if (i.key == "imm.KEY" || i.default_text.find(' ') != std::string::npos) continue;
    FilterOptions o;
    CHECK_NOTHROW(apply_settings(std::vector<Setting>{parse_setting(i.key + "=" + i.default_text, "--set")}, o));
  }
}
