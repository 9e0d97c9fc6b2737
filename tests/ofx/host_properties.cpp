#include "host_properties.h"

#include <stdexcept>

namespace taa::ofxtest {
namespace {

template <class T>
OfxStatus setValue(OfxPropertySetHandle h, const char* name, int index, T value) {
  if (!h || !name || index < 0) return kOfxStatErrBadHandle;
  auto& values = PropertySet::from(h)->values[name];
  if (int(values.size()) <= index) values.resize(index + 1, PropertyValue(T{}));
  values[index] = PropertyValue(std::move(value));
  return kOfxStatOK;
}

template <class T>
OfxStatus setValues(OfxPropertySetHandle h, const char* name, int count, const T* value) {
  if (!h || !name || count < 0) return kOfxStatErrBadHandle;
  auto& values = PropertySet::from(h)->values[name];
  values.clear();
  for (int i = 0; i < count; ++i) values.emplace_back(T(value[i]));
  return kOfxStatOK;
}

const PropertyValue* find(OfxPropertySetHandle h, const char* name, int index,
                          OfxStatus& status) {
  status = kOfxStatErrUnknown;
  if (!h || !name) return nullptr;
  const auto& values = PropertySet::from(h)->values;
  const auto it = values.find(name);
  if (it == values.end()) return nullptr;
  status = kOfxStatErrBadIndex;
  if (index < 0 || index >= int(it->second.size())) return nullptr;
  status = kOfxStatOK;
  return &it->second[index];
}

// Ints and doubles convert into each other, as hosts allow for numeric properties.
template <class T>
OfxStatus getValue(OfxPropertySetHandle h, const char* name, int index, T* out) {
  OfxStatus status;
  const PropertyValue* value = find(h, name, index, status);
  if (!value) return status;
  if constexpr (std::is_same_v<T, int> || std::is_same_v<T, double>) {
    if (auto i = std::get_if<int>(value)) *out = T(*i);
    else if (auto d = std::get_if<double>(value)) *out = T(*d);
    else return kOfxStatErrValue;
  } else if constexpr (std::is_same_v<T, char*>) {
    auto s = std::get_if<std::string>(value);
    if (!s) return kOfxStatErrValue;
    *out = const_cast<char*>(s->c_str());
  } else {
    auto p = std::get_if<void*>(value);
    if (!p) return kOfxStatErrValue;
    *out = *p;
  }
  return kOfxStatOK;
}

template <class T>
OfxStatus getValues(OfxPropertySetHandle h, const char* name, int count, T* out) {
  for (int i = 0; i < count; ++i) {
    const OfxStatus status = getValue(h, name, i, &out[i]);
    if (status != kOfxStatOK) return status;
  }
  return kOfxStatOK;
}

OfxStatus setString(OfxPropertySetHandle h, const char* name, int index, const char* value) {
  return setValue(h, name, index, std::string(value ? value : ""));
}

OfxStatus setStrings(OfxPropertySetHandle h, const char* name, int count,
                     const char* const* value) {
  if (!h || !name || count < 0) return kOfxStatErrBadHandle;
  auto& values = PropertySet::from(h)->values[name];
  values.clear();
  for (int i = 0; i < count; ++i) values.emplace_back(std::string(value[i]));
  return kOfxStatOK;
}

OfxStatus reset(OfxPropertySetHandle h, const char* name) {
  if (!h || !name) return kOfxStatErrBadHandle;
  PropertySet::from(h)->values.erase(name);
  return kOfxStatOK;
}

OfxStatus dimension(OfxPropertySetHandle h, const char* name, int* count) {
  if (!h || !name || !count) return kOfxStatErrBadHandle;
  const auto& values = PropertySet::from(h)->values;
  const auto it = values.find(name);
  if (it == values.end()) return kOfxStatErrUnknown;
  *count = int(it->second.size());
  return kOfxStatOK;
}

const OfxPropertySuiteV1 kSuite = {
    setValue<void*>,      setString,          setValue<double>,     setValue<int>,
    setValues<void*>,     setStrings,         setValues<double>,    setValues<int>,
    getValue<void*>,      getValue<char*>,    getValue<double>,     getValue<int>,
    getValues<void*>,     getValues<char*>,   getValues<double>,    getValues<int>,
    reset,                dimension,
};

}  // namespace

int PropertySet::dimension(const std::string& name) const {
  const auto it = values.find(name);
  return it == values.end() ? 0 : int(it->second.size());
}

int PropertySet::getInt(const std::string& name, int index) const {
  return std::get<int>(values.at(name).at(index));
}

double PropertySet::getDouble(const std::string& name, int index) const {
  const PropertyValue& v = values.at(name).at(index);
  if (auto i = std::get_if<int>(&v)) return *i;
  return std::get<double>(v);
}

std::string PropertySet::getString(const std::string& name, int index) const {
  return std::get<std::string>(values.at(name).at(index));
}

void* PropertySet::getPointer(const std::string& name, int index) const {
  return std::get<void*>(values.at(name).at(index));
}

std::vector<std::string> PropertySet::strings(const std::string& name) const {
  std::vector<std::string> out;
  const auto it = values.find(name);
  if (it == values.end()) return out;
  for (const auto& v : it->second) out.push_back(std::get<std::string>(v));
  return out;
}

const OfxPropertySuiteV1* propertySuite() { return &kSuite; }

}  // namespace taa::ofxtest
