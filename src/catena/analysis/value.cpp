#include "catena/analysis/value.hpp"

#include <cmath>

namespace catena::analysis {

Value::Value(const std::vector<double>& values) {
  Array a;
  a.reserve(values.size());
  for (double v : values) a.emplace_back(v);
  data_ = std::move(a);
}

Value::Value(const std::optional<double>& value) {
  if (value) data_ = *value;
}

Value Value::object(std::initializer_list<Member> members) {
  Value v = object();
  for (const Member& m : members) v[m.first] = m.second;
  return v;
}

double Value::as_number() const {
  if (is_real()) return std::get<double>(data_);
  if (is_integer()) return static_cast<double>(std::get<std::int64_t>(data_));
  return NAN;
}

Value& Value::operator[](std::string_view key) {
  if (is_null()) data_ = Object{};
  Object& members = std::get<Object>(data_);
  for (Member& m : members) {
    if (m.first == key) return m.second;
  }
  members.emplace_back(std::string(key), Value());
  return members.back().second;
}

const Value* Value::find(std::string_view key) const {
  if (!is_object()) return nullptr;
  for (const Member& m : std::get<Object>(data_)) {
    if (m.first == key) return &m.second;
  }
  return nullptr;
}

const Value& Value::at(std::string_view key) const {
  static const Value null;
  const Value* v = find(key);
  return v ? *v : null;
}

void Value::push_back(Value v) {
  if (is_null()) data_ = Array{};
  std::get<Array>(data_).push_back(std::move(v));
}

std::size_t Value::size() const {
  if (is_array()) return std::get<Array>(data_).size();
  if (is_object()) return std::get<Object>(data_).size();
  return 0;
}

std::vector<double> Value::numbers(double scale) const {
  std::vector<double> out;
  if (!is_array()) return out;
  out.reserve(size());
  for (const Value& v : as_array()) out.push_back(v.is_number() ? v.as_number() * scale : NAN);
  return out;
}

bool Value::has_non_finite() const {
  if (is_real()) return !std::isfinite(std::get<double>(data_));
  if (is_array()) {
    for (const Value& v : as_array()) {
      if (v.has_non_finite()) return true;
    }
  }
  if (is_object()) {
    for (const Member& m : as_object()) {
      if (m.second.has_non_finite()) return true;
    }
  }
  return false;
}

}  // namespace catena::analysis
