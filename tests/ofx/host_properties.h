// The test host's property sets and its OfxPropertySuiteV1: typed, multi-dimensional values by
// name, as a host keeps them for effects, clips, images, parameters and action arguments.
#pragma once

#include <map>
#include <string>
#include <variant>
#include <vector>

#include "ofx/ofx_abi.h"

namespace taa::ofxtest {

using PropertyValue = std::variant<int, double, std::string, void*>;

struct PropertySet {
  std::map<std::string, std::vector<PropertyValue>> values;

  OfxPropertySetHandle handle() { return reinterpret_cast<OfxPropertySetHandle>(this); }
  static PropertySet* from(OfxPropertySetHandle h) { return reinterpret_cast<PropertySet*>(h); }

  bool has(const std::string& name) const { return values.count(name) != 0; }
  int dimension(const std::string& name) const;
  // Typed reads for the checks; a missing property or index fails with std::out_of_range.
  int getInt(const std::string& name, int index = 0) const;
  double getDouble(const std::string& name, int index = 0) const;
  std::string getString(const std::string& name, int index = 0) const;
  void* getPointer(const std::string& name, int index = 0) const;
  std::vector<std::string> strings(const std::string& name) const;
  void set(const std::string& name, std::vector<PropertyValue> value) { values[name] = value; }
};

const OfxPropertySuiteV1* propertySuite();

}  // namespace taa::ofxtest
