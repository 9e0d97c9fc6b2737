// The host's suites, fetched once in setHost/kOfxActionLoad and used by every action.
#pragma once

#include "ofx/ofx_abi.h"

namespace taa::ofx {

struct HostSuites {
  OfxHost* host = nullptr;
  const OfxPropertySuiteV1* properties = nullptr;
  const OfxImageEffectSuiteV1* effects = nullptr;
  const OfxParameterSuiteV1* parameters = nullptr;
  const OfxMessageSuiteV1* messages = nullptr;  // optional
};

HostSuites& suites();

// Fetches the suites from the host given to setHost; false when a required one is missing.
bool fetchSuites();

// Reports `text` to the host's message suite as an error on `effect`, when the host has one.
void reportError(OfxImageEffectHandle effect, const char* text);

}  // namespace taa::ofx
