#include <doctest/doctest.h>

#include <cstring>

#include "mptrack/status.h"

using mptrack::Status;

namespace {
Status fails_at(int step, int failing_step) {
  return step == failing_step ? Status::kInvalidArgument : Status::kOk;
}
Status chain(int failing_step, int* reached) {
  for (int step = 0; step < 3; ++step) {
    *reached = step;
    MPTRACK_TRY(fails_at(step, failing_step));
  }
  return Status::kOk;
}
}  // namespace

TEST_CASE("every status has a distinct stable name") {
  const Status all[] = {Status::kOk,          Status::kInvalidArgument, Status::kInvalidInput,
                        Status::kCapacityExceeded, Status::kOutOfOrder,  Status::kNumericalError,
                        Status::kNotInitialized, Status::kBufferFull,    Status::kBufferEmpty,
                        Status::kPartial};
  for (std::size_t i = 0; i < sizeof all / sizeof all[0]; ++i) {
    CHECK(std::strcmp(mptrack::to_string(all[i]), "unknown") != 0);
    for (std::size_t j = 0; j < i; ++j) {
      CHECK(std::strcmp(mptrack::to_string(all[i]), mptrack::to_string(all[j])) != 0);
    }
  }
  CHECK(std::strcmp(mptrack::to_string(Status::kCapacityExceeded), "capacity_exceeded") == 0);
}

TEST_CASE("MPTRACK_TRY returns the first failure and stops the chain") {
  int reached = -1;
  CHECK(chain(1, &reached) == Status::kInvalidArgument);
  CHECK(reached == 1);
  CHECK(chain(99, &reached) == Status::kOk);
  CHECK(reached == 2);
}

TEST_CASE("first_error keeps the earliest failure") {
  CHECK(mptrack::first_error(Status::kOk, Status::kBufferFull) == Status::kBufferFull);
  CHECK(mptrack::first_error(Status::kInvalidInput, Status::kBufferFull) == Status::kInvalidInput);
  CHECK(mptrack::ok(Status::kOk));
  CHECK_FALSE(mptrack::ok(Status::kPartial));
}
