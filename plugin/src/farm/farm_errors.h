// The failures taa-farm tells apart by exit status (farm/main.cpp): a scheduler retries or
// reports each differently. Anything else taa throws is a resolve error (status 1).
#pragma once

#include "taa/error.h"

namespace taa::farm {

// Bad arguments: exit status 2.
class UsageError : public Error {
 public:
  using Error::Error;
};

// An input frame the task needs is not on disk yet (a render still running or failed): exit
// status 3. Requeue the task once it is there.
class InputsNotReady : public Error {
 public:
  using Error::Error;
};

}  // namespace taa::farm
