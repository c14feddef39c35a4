// SPDX-License-Identifier: Apache-2.0
// The PCL and sonar trackers' keys (filters/sensor_settings.hpp): --set
// and --config reach the tracker parameters, a bad key or value is refused
// naming it and changes nothing, the summary echo names every key, and
// docs/parameters.md gives every key with the default the code has.
#include <catch2/catch.hpp>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "filters/sensor_settings.hpp"
#include "montecarlo/pcl_run.hpp"
#include "montecarlo/sonar_run.hpp"

using namespace kestrel;       // NOLINT(google-build-using-namespace)
using namespace kestrel::sim;  // NOLINT(google-build-using-namespace)

namespace {
std::vector<Setting> sets(const std::vector<std::string>& texts) {
  std::vector<Setting> s;
  for (const std::string& t : texts) s.push_back(parse_setting(t, "--set"));
  return s;
}

template <class Params, class Apply>
std::string refusal(const std::vector<std::string>& texts, Params& p, Apply apply) {
  try {
    apply(sets(texts), p);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}
}  // namespace

SCENARIO("PCL tracker keys set PclTrackerParams", "[settings][pcl]") {
  GIVEN("pcl002's tracker parameters") {
    const PclTrackerParams base = pcl_params_for(pcl002_config());
    WHEN("keys of every type are set") {
      PclTrackerParams p = base;
      apply_pcl_settings(sets({"accel_sigma_mps2=2.5", "gate_confirmed=0.999", "confirm_m=3", "confirm_n=4",
                               "max_coast_misses=9", "detection_probability=0.7"}),
                         p);
      THEN("each reaches its field and the others keep the scenario's values") {
        CHECK(p.accel_sigma_mps2 == 2.5);
        CHECK(p.gate_confirmed == GateProbability::k999);
        CHECK(p.confirm_m == 3);
        CHECK(p.confirm_n == 4);
        CHECK(p.max_coast_misses == 9);
        CHECK(p.detection_probability == 0.7);
        CHECK(p.sigma_rb_m == base.sigma_rb_m);
        CHECK(p.clutter_density == base.clutter_density);
        CHECK(p.gate_tentative == base.gate_tentative);
      }
      THEN("the echo gives every key with the value used") {
        const auto echo = pcl_parameters(p);
        CHECK(echo.size() == pcl_setting_table().size());
        CHECK(echo.at("accel_sigma_mps2") == 2.5);
        CHECK(echo.at("gate_confirmed") == 0.999);
        CHECK(echo.at("confirm_n") == 4.0);
      }
    }
    WHEN("a key is unknown, a value out of range, or M exceeds N") {
      PclTrackerParams p = base;
      const auto apply = [](const std::vector<Setting>& s, PclTrackerParams& q) { apply_pcl_settings(s, q); };
      THEN("each is refused by name and nothing changes") {
        CHECK_THAT(refusal({"accel_sigma_mps2=3", "qj=5"}, p, apply),
                   Catch::Contains("--set qj=5: unknown key of the PCL tracker (known: sigma_rb_m,"));
        CHECK_THAT(refusal({"qj=5"}, p, apply), Catch::EndsWith("`kestrel-sim list --settings`"));
        // A key of another tracker says whose it is; a key of none does not.
        CHECK_THAT(refusal({"qj=5"}, p, apply),
                   Catch::Contains("); it is a key of the radar tracker. The keys of each tracker"));
        CHECK_THAT(refusal({"bogus=5"}, p, apply), !Catch::Contains("it is a key of"));
        CHECK_THAT(refusal({"confirm_m=9"}, p, apply), Catch::Contains("--set confirm_m=9: out of range (whole, 1..8)"));
        CHECK_THAT(refusal({"gate_tentative=0.97"}, p, apply), Catch::Contains("out of range (0.9, 0.95, 0.99"));
        CHECK_THAT(refusal({"detection_probability=1"}, p, apply), Catch::Contains("out of range (> 0, < 1)"));
        CHECK_THAT(refusal({"confirm_m=2.5"}, p, apply), Catch::Contains("out of range"));
        CHECK_THAT(refusal({"confirm_m=7"}, p, apply), Catch::Contains("confirm_m 7 > confirm_n 6"));
        CHECK(p.accel_sigma_mps2 == base.accel_sigma_mps2);
        CHECK(p.confirm_m == base.confirm_m);
      }
    }
  }
}

SCENARIO("Sonar tracker keys set SonarTrackerParams", "[settings][sonar]") {
  GIVEN("uw003's tracker parameters") {
    const SonarTrackerParams base = sonar_params_for(uw003_config());
    WHEN("a real, a boolean, a gate and a whole key are set") {
      SonarTrackerParams p = base;
      apply_sonar_settings(sets({"gate_k_sigma=3", "per_channel_gate=false", "ellipsoidal_gate=true",
                                 "ellipsoid_probability=0.95", "reacquire_after_lost_frames=0"}),
                        p);
      THEN("each reaches its field") {
        CHECK(p.gate_k_sigma == 3.0);
        CHECK_FALSE(p.per_channel_gate);
        CHECK(p.ellipsoidal_gate);
        CHECK(p.ellipsoid_probability == GateProbability::k95);
        CHECK(p.reacquire_after_lost_frames == 0);
        CHECK(p.seabed_depth_m == base.seabed_depth_m);
        CHECK(sonar_parameters(p).at("per_channel_gate") == 0.0);
      }
    }
    WHEN("a boolean gets 2 or a radar key is given") {
      SonarTrackerParams p = base;
      const auto apply = [](const std::vector<Setting>& s, SonarTrackerParams& q) { apply_sonar_settings(s, q); };
      THEN("it is refused by name and nothing changes") {
        CHECK_THAT(refusal({"gate_k_sigma=3", "project_depth=2"}, p, apply),
                   Catch::Contains("--set project_depth=2: out of range (false or true)"));
        CHECK_THAT(refusal({"gate_k=3"}, p, apply), Catch::Contains("unknown key of the sonar tracker"));
        CHECK_THAT(refusal({"sigma_rb_m=3"}, p, apply), Catch::Contains("; it is a key of the PCL tracker."));
        CHECK(p.gate_k_sigma == base.gate_k_sigma);
      }
    }
  }
}

SCENARIO("docs/parameters.md gives every PCL and underwater key with its default", "[settings]") {
  std::ifstream in(KESTREL_DOCS_DIR "/parameters.md");
  REQUIRE(in);
  std::stringstream doc;
  doc << in.rdbuf();
  for (const auto& table : {pcl_setting_table(), sonar_setting_table()}) {
    for (const SettingInfo& i : table) {
      INFO(i.key);
      CHECK(doc.str().find("| `" + i.key + "` | " + i.default_text + " | " + i.range + " |") != std::string::npos);
    }
  }
  THEN("each default that is a number or a boolean is accepted back") {
    PclTrackerParams p = pcl_params_for(pcl002_config());
    for (const SettingInfo& i : pcl_setting_table()) {
      if (i.default_text.find(' ') != std::string::npos) continue;
      INFO(i.key);
      CHECK_NOTHROW(apply_pcl_settings(sets({i.key + "=" + i.default_text}), p));
    }
    SonarTrackerParams u = sonar_params_for(uw003_config());
    for (const SettingInfo& i : sonar_setting_table()) {
      if (i.default_text.find(' ') != std::string::npos) continue;
      INFO(i.key);
      CHECK_NOTHROW(apply_sonar_settings(sets({i.key + "=" + i.default_text}), u));
    }
  }
}

SCENARIO("A key of another tracker than the one of the frames' kind is refused as such", "[settings][replay]") {
  const auto refused = [](const std::vector<std::string>& texts, hal::FrameKind kind) -> std::string {
    try {
      check_settings_kind(sets(texts), kind, "s.kstr holds frames of that kind");
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  GIVEN("keys of each tracker") {
    THEN("each tracker takes its own, a key two trackers share included") {
      CHECK(refused({"qj=5", "confirm_m=3", "imm.p_stay=0.9", "board_gate=true"}, hal::FrameKind::kRadar).empty());
      CHECK(refused({"sigma_rb_m=12", "confirm_m=3", "gate_confirmed=0.999"}, hal::FrameKind::kPcl).empty());
      CHECK(refused({"gate_k_sigma=3", "per_channel_gate=false"}, hal::FrameKind::kSonar).empty());
    }
    THEN("a key of another tracker names itself, the kind's tracker, whose key it is and list --settings") {
      CHECK_THAT(refused({"confirm_m=3", "qj=5"}, hal::FrameKind::kPcl),
                 Catch::Equals("--set qj=5: 'qj' is not a key of the PCL tracker (s.kstr holds frames of that kind); "
                               "it is a key of the radar tracker. The keys of each tracker: `kestrel-sim list "
                               "--settings`"));
      CHECK_THAT(refused({"confirm_m=3"}, hal::FrameKind::kSonar),
                 Catch::Contains("'confirm_m' is not a key of the sonar tracker") &&
                     Catch::Contains("it is a key of the radar and PCL trackers."));
      CHECK_THAT(refused({"gate_k_sigma=3"}, hal::FrameKind::kRadar),
                 Catch::Contains("--set gate_k_sigma=3: 'gate_k_sigma' is not a key of the radar tracker") &&
                     Catch::Contains("it is a key of the sonar tracker"));
      CHECK_THAT(refused({"imm.p_stay=0.9"}, hal::FrameKind::kPcl), Catch::Contains("a key of the radar tracker"));
      CHECK_THAT(refused({"sa=1"}, hal::FrameKind::kSonar),
                 Catch::Contains("'sa' is not a key of the sonar tracker") &&
                     Catch::Contains("no tracker has it") && Catch::Contains("`kestrel-sim list --settings`"));
    }
  }
}
