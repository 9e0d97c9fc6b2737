#include "ofx/host_suites.h"

namespace taa::ofx {

HostSuites& suites() {
  static HostSuites instance;
  return instance;
}

bool fetchSuites() {
  HostSuites& s = suites();
  if (!s.host || !s.host->fetchSuite) return false;
  auto fetch = [&](const char* name) { return s.host->fetchSuite(s.host->host, name, 1); };
  s.properties = static_cast<const OfxPropertySuiteV1*>(fetch(kOfxPropertySuite));
  s.effects = static_cast<const OfxImageEffectSuiteV1*>(fetch(kOfxImageEffectSuite));
  s.parameters = static_cast<const OfxParameterSuiteV1*>(fetch(kOfxParameterSuite));
  s.messages = static_cast<const OfxMessageSuiteV1*>(fetch(kOfxMessageSuite));
  return s.properties && s.effects && s.parameters;
}

void reportError(OfxImageEffectHandle effect, const char* text) {
  const HostSuites& s = suites();
  if (s.messages && s.messages->message) {
    s.messages->message(effect, kOfxMessageError, nullptr, "%s", text);
  }
}

}  // namespace taa::ofx
