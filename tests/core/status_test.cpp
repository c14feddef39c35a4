// SPDX-License-Identifier: Apache-2.0
// KESTREL_TRY and KESTREL_TRY_OR: a failure returns at once (with the
// handler's result for _OR), kOk falls through, the expression runs once.
#include <catch2/catch.hpp>

#include "kestrel/status.hpp"

namespace {

struct Calls {
  int evaluated = 0;
  int reached_end = 0;
  int handled = 0;
};

kestrel::Status give(kestrel::Status s, Calls& c) {
  ++c.evaluated;
  return s;
}

kestrel::Status chain(kestrel::Status first, kestrel::Status second, Calls& c) {
  KESTREL_TRY(give(first, c));
  KESTREL_TRY(give(second, c));
  ++c.reached_end;
  return kestrel::Status::kOk;
}

kestrel::Status chain_or(kestrel::Status first, Calls& c) {
  const auto fail = [&c](kestrel::Status s) {
    ++c.handled;
    return s;
  };
  KESTREL_TRY_OR(fail, give(first, c));
  ++c.reached_end;
  return kestrel::Status::kOk;
}

}  // namespace

SCENARIO("KESTREL_TRY propagates the first failure and evaluates each expression once", "[status]") {
  using kestrel::Status;
  GIVEN("two steps that succeed") {
    Calls c;
    CHECK(chain(Status::kOk, Status::kOk, c) == Status::kOk);
    THEN("both ran once and the function reached its end") {
      CHECK(c.evaluated == 2);
      CHECK(c.reached_end == 1);
    }
  }
  GIVEN("a first step that fails") {
    Calls c;
    CHECK(chain(Status::kNotPositiveDefinite, Status::kOk, c) == Status::kNotPositiveDefinite);
    THEN("the second never ran and the end was not reached") {
      CHECK(c.evaluated == 1);
      CHECK(c.reached_end == 0);
    }
  }
  GIVEN("a second step that fails") {
    Calls c;
    CHECK(chain(Status::kOk, Status::kNonFinite, c) == Status::kNonFinite);
    CHECK(c.evaluated == 2);
    CHECK(c.reached_end == 0);
  }
  GIVEN("KESTREL_TRY_OR with a handler") {
    Calls ok;
    CHECK(chain_or(Status::kOk, ok) == Status::kOk);
    CHECK(ok.handled == 0);
    CHECK(ok.reached_end == 1);
    Calls bad;
    CHECK(chain_or(Status::kOutOfRange, bad) == Status::kOutOfRange);
    THEN("the handler saw the failure once and its result was returned") {
      CHECK(bad.handled == 1);
      CHECK(bad.evaluated == 1);
      CHECK(bad.reached_end == 0);
    }
  }
}
