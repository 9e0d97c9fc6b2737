// The host's suites, fetched once in setHost/kOfxActionLoad and used by every action.
#pragma once

#include "ofx/ofx_abi.h"

namespace taa::ofx {

struct HostSuites {
  OfxHost* host = nullptr;
  const OfxPropertySuiteV1* properties = nullptr;
  const OfxImageEffectSuiteV1* effects = nullptr;
  const OfxParameterSuiteV1* parameters = nullptr;
  // Optional. Version 2 where the host has it (persistent messages), else version 1 seen
  // through version 2's first member; persistentMessages says which.
  const OfxMessageSuiteV2* messages = nullptr;
  bool persistentMessages = false;
};

HostSuites& suites();

// Fetches the suites from the host given to setHost; false when a required one is missing.
bool fetchSuites();

// Reports `text` as an error on `effect`: a persistent message (it stays on the effect until
// cleared: hosts show it on the node) where the host has them, else a transient one.
void reportError(OfxImageEffectHandle effect, const char* text);

// Clears a persistent message reportError left on `effect`.
void clearError(OfxImageEffectHandle effect);

}  // namespace taa::ofx
