// A small JSON reader and writer for the budgets file and bench reports. Strict: malformed input
// raises InputError with the byte offset.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace bvb::json {

struct Value {
  enum Type { Null, Bool, Number, String, Array, Object } type = Null;
  bool b = false;
  double num = 0;
  std::string str;
  std::vector<Value> arr;
  std::vector<std::pair<std::string, Value>> obj;  // keeps file order

  const Value *get(const std::string &key) const;
};

Value parse(const std::string &text, const std::string &name);
std::string quote(const std::string &s);

}  // namespace bvb::json
