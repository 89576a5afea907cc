// A result value as a tree: null, true/false, a whole number, a real number, text, a list, or
// named members in order. An analysis' `describe` builds its result as one Value; the writers in
// io/ turn it into JSON, CSV, tables and report sections, and the Python module into dicts.
// Integers and reals are kept apart so that JSON shows `8` for a tooth count and `8.0` for a
// length that happens to be whole. Non-finite reals are kept as they are (JSON writes null; a
// front end can find them with `has_non_finite`).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace catena::analysis {

class Value {
 public:
  using Array = std::vector<Value>;
  using Member = std::pair<std::string, Value>;
  using Object = std::vector<Member>;  ///< in insertion order; keys unique

  Value() = default;  ///< null
  Value(std::nullptr_t) {}
  Value(bool b) : data_(b) {}
  Value(int i) : data_(std::int64_t{i}) {}
  Value(long i) : data_(std::int64_t{i}) {}
  Value(long long i) : data_(std::int64_t{i}) {}
  Value(unsigned i) : data_(std::int64_t{i}) {}
  Value(unsigned long i) : data_(static_cast<std::int64_t>(i)) {}
  Value(double d) : data_(d) {}
  Value(const char* s) : data_(std::string(s)) {}
  Value(std::string s) : data_(std::move(s)) {}
  Value(std::string_view s) : data_(std::string(s)) {}
  /// A list of reals (a series).
  Value(const std::vector<double>& values);
  /// An optional real: null when empty.
  Value(const std::optional<double>& value);
  Value(Array a) : data_(std::move(a)) {}

  static Value array() { return Value(Array{}); }
  static Value object() {
    Value v;
    v.data_ = Object{};
    return v;
  }
  /// An object from (key, value) pairs in order.
  static Value object(std::initializer_list<Member> members);

  bool is_null() const { return std::holds_alternative<std::monostate>(data_); }
  bool is_bool() const { return std::holds_alternative<bool>(data_); }
  bool is_integer() const { return std::holds_alternative<std::int64_t>(data_); }
  bool is_real() const { return std::holds_alternative<double>(data_); }
  bool is_number() const { return is_integer() || is_real(); }
  bool is_string() const { return std::holds_alternative<std::string>(data_); }
  bool is_array() const { return std::holds_alternative<Array>(data_); }
  bool is_object() const { return std::holds_alternative<Object>(data_); }

  bool as_bool() const { return std::get<bool>(data_); }
  std::int64_t as_integer() const { return std::get<std::int64_t>(data_); }
  /// A number as a real (integers converted); NaN for anything else.
  double as_number() const;
  const std::string& as_string() const { return std::get<std::string>(data_); }
  const Array& as_array() const { return std::get<Array>(data_); }
  Array& as_array() { return std::get<Array>(data_); }
  const Object& as_object() const { return std::get<Object>(data_); }
  Object& as_object() { return std::get<Object>(data_); }

  /// Object member `key`, inserted (as null) when absent. A null value becomes an object first.
  Value& operator[](std::string_view key);
  /// Object member `key`, or nullptr when this is not an object or has no such member.
  const Value* find(std::string_view key) const;
  bool contains(std::string_view key) const { return find(key) != nullptr; }
  /// Object member `key`; a static null when absent.
  const Value& at(std::string_view key) const;
  /// Appends to an array (a null value becomes an array first).
  void push_back(Value v);
  /// Elements of an array or members of an object; 0 otherwise.
  std::size_t size() const;
  /// The numbers of an array of numbers (others as NaN), times `scale`.
  std::vector<double> numbers(double scale = 1.0) const;
  /// True when any real in the tree is NaN or infinite.
  bool has_non_finite() const;

 private:
  std::variant<std::monostate, bool, std::int64_t, double, std::string, Array, Object> data_;
};

}  // namespace catena::analysis
