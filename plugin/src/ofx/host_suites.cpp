#include "ofx/host_suites.h"

namespace taa::ofx {

HostSuites& suites() {
  static HostSuites instance;
  return instance;
}

bool fetchSuites() {
  HostSuites& s = suites();
  if (!s.host || !s.host->fetchSuite) return false;
  auto fetch = [&](const char* name, int version) {
    return s.host->fetchSuite(s.host->host, name, version);
  };
  s.properties = static_cast<const OfxPropertySuiteV1*>(fetch(kOfxPropertySuite, 1));
  s.effects = static_cast<const OfxImageEffectSuiteV1*>(fetch(kOfxImageEffectSuite, 1));
  s.parameters = static_cast<const OfxParameterSuiteV1*>(fetch(kOfxParameterSuite, 1));
  s.messages = static_cast<const OfxMessageSuiteV2*>(fetch(kOfxMessageSuite, 2));
  s.persistentMessages = s.messages != nullptr;
  if (!s.messages) s.messages = static_cast<const OfxMessageSuiteV2*>(fetch(kOfxMessageSuite, 1));
  return s.properties && s.effects && s.parameters;
}

void reportError(OfxImageEffectHandle effect, const char* text) {
  const HostSuites& s = suites();
  if (!s.messages) return;
  if (s.persistentMessages && effect && s.messages->setPersistentMessage &&
      s.messages->setPersistentMessage(effect, kOfxMessageError, nullptr, "%s", text) ==
          kOfxStatOK) {
    return;
  }
  if (s.messages->message) s.messages->message(effect, kOfxMessageError, nullptr, "%s", text);
}

void clearError(OfxImageEffectHandle effect) {
  const HostSuites& s = suites();
  if (s.persistentMessages && effect && s.messages->clearPersistentMessage) {
    s.messages->clearPersistentMessage(effect);
  }
}

}  // namespace taa::ofx
