#include "friction/law_spec.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <system_error>

namespace frictionlab::friction {
namespace {

bool is_alpha(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }

bool valid_name(std::string_view s) {
  if (s.empty() || !(is_alpha(s[0]) || is_digit(s[0]))) return false;
  return std::all_of(s.begin(), s.end(), [](char c) {
    return is_alpha(c) || is_digit(c) || c == '.' || c == '_' || c == '+' || c == '-';
  });
}

bool valid_key(std::string_view s) {
  if (s.empty() || !(is_alpha(s[0]) || s[0] == '_')) return false;
  return std::all_of(s.begin(), s.end(), [](char c) { return is_alpha(c) || is_digit(c) || c == '_'; });
}

bool valid_value(std::string_view s) {
  return !s.empty() && std::none_of(s.begin(), s.end(), [](char c) {
    return c == ',' || c == ';' || c == ':' || c == '=' || is_space(c);
  });
}

std::string quoted(std::string_view s) { return "'" + std::string(s) + "'"; }

[[noreturn]] void bad_spec(std::string_view spec, const std::string& why) {
  throw std::invalid_argument("friction law spec " + quoted(spec) + " is invalid: " + why);
}

// Shortest text that reads back as the same double.
std::string shortest(double x) {
  std::array<char, 32> buf{};
  const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), x);
  return std::string(buf.data(), r.ptr);
}

std::string bound(double x) {
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  return shortest(x);
}

// A finite double from the whole of `text` (C locale, optional leading '+'), or nothing.
std::optional<double> parse_number(std::string_view text) {
  std::string_view t = text;
  if (!t.empty() && t.front() == '+') {
    t.remove_prefix(1);
    if (!t.empty() && (t.front() == '+' || t.front() == '-')) return std::nullopt;
  }
  double x = 0.0;
  const auto r = std::from_chars(t.data(), t.data() + t.size(), x, std::chars_format::general);
  if (r.ec != std::errc() || r.ptr != t.data() + t.size() || !std::isfinite(x)) return std::nullopt;
  return x;
}

bool in_range(const LawParameter& p, double x) {
  if (p.min_open ? !(x > p.min) : !(x >= p.min)) return false;
  if (p.max_open ? !(x < p.max) : !(x <= p.max)) return false;
  return true;
}

std::string joined(const std::vector<std::string>& v, const char* sep) {
  std::string out;
  for (const auto& s : v) out += (out.empty() ? "" : sep) + s;
  return out;
}

std::string keys_of(const std::vector<LawParameter>& params) {
  std::vector<std::string> keys;
  for (const auto& p : params) keys.push_back(p.key);
  return joined(keys, ", ");
}

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

// An item of a comma list that reads KEY=VALUE: it has an '=' and no ':' before it.
bool is_parameter_item(std::string_view item) {
  const std::size_t eq = item.find('=');
  return eq != std::string_view::npos && item.substr(0, eq).find(':') == std::string_view::npos;
}

}  // namespace

LawParameter LawParameter::choice(std::string key, std::vector<std::string> choices, std::string default_value,
                                  std::string doc) {
  LawParameter p;
  p.key = std::move(key);
  p.kind = Kind::choice;
  p.choices = std::move(choices);
  p.default_value = std::move(default_value);
  p.doc = std::move(doc);
  return p;
}

LawParameter LawParameter::number(std::string key, double min, bool min_open, double max, bool max_open,
                                  std::string unit, std::optional<double> default_value, std::string default_doc,
                                  std::string doc) {
  LawParameter p;
  p.key = std::move(key);
  p.kind = Kind::number;
  p.min = min;
  p.max = max;
  p.min_open = min_open;
  p.max_open = max_open;
  p.unit = std::move(unit);
  if (default_value) p.default_value = shortest(*default_value);
  p.default_doc = std::move(default_doc);
  p.doc = std::move(doc);
  return p;
}

std::string LawParameter::rule() const {
  if (kind == Kind::choice) return "one of " + joined(choices, ", ");
  std::string r = "a finite number in ";
  r += (min_open || std::isinf(min)) ? "(" : "[";  // an infinite end is never reached: open
  r += bound(min) + ", " + bound(max);
  r += (max_open || std::isinf(max)) ? ")" : "]";
  if (!unit.empty()) r += " " + unit;
  return r;
}

std::string LawParameter::describe() const {
  std::string d = key + " = " + (kind == Kind::choice ? joined(choices, "|") : rule());
  d += default_value.empty() ? " (default: " + default_doc + ")" : " (default " + default_value + ")";
  return d + ": " + doc;
}

ParsedLawSpec parse_law_spec(std::string_view spec) {
  if (spec.empty()) bad_spec(spec, "it is empty: give a law name, e.g. exact, or NAME:KEY=VALUE");
  if (std::any_of(spec.begin(), spec.end(), is_space)) {
    bad_spec(spec, "it contains white space: write NAME or NAME:KEY=VALUE[,KEY=VALUE] without spaces");
  }
  ParsedLawSpec out;
  out.text = std::string(spec);
  const std::size_t colon = spec.find(':');
  const std::string_view name = spec.substr(0, colon);
  if (!valid_name(name)) {
    bad_spec(spec, "the law name " + quoted(name) +
                       " is not a name (letters, digits and . _ + -, starting with a letter or digit)");
  }
  out.name = std::string(name);
  if (colon == std::string_view::npos) return out;
  std::string_view rest = spec.substr(colon + 1);
  if (rest.empty()) bad_spec(spec, "no parameters after ':': write NAME:KEY=VALUE[,KEY=VALUE], or NAME alone");
  while (true) {
    const std::size_t comma = rest.find(',');
    const std::string_view item = rest.substr(0, comma);
    if (item.empty()) bad_spec(spec, "it has an empty parameter: separate KEY=VALUE pairs by one comma");
    const std::size_t eq = item.find('=');
    const std::string_view key = item.substr(0, eq);
    if (key.empty()) bad_spec(spec, "it has an empty key in " + quoted(item) + ": write KEY=VALUE");
    if (!valid_key(key)) {
      bad_spec(spec, "the key " + quoted(key) +
                         " is not a key (letters, digits and _, starting with a letter or _)");
    }
    if (eq == std::string_view::npos) {
      bad_spec(spec, "the parameter " + quoted(key) + " has no value: write KEY=VALUE");
    }
    const std::string_view value = item.substr(eq + 1);
    if (value.empty()) bad_spec(spec, "the parameter " + quoted(key) + " has an empty value: write KEY=VALUE");
    if (!valid_value(value)) {
      bad_spec(spec, "the value " + quoted(value) + " of " + std::string(key) +
                         " is not a value (no , ; : = or white space in it)");
    }
    out.arguments.emplace_back(std::string(key), std::string(value));
    if (comma == std::string_view::npos) break;
    rest = rest.substr(comma + 1);
  }
  return out;
}

std::vector<std::string> split_law_list(std::string_view list) {
  if (trimmed(list).empty()) throw std::invalid_argument("the law list " + quoted(list) + " is empty: give at least one law");
  const auto bad_list = [&](const std::string& why) {
    throw std::invalid_argument("the law list " + quoted(list) + " is invalid: " + why);
  };
  std::vector<std::string> out;
  std::size_t start = 0;
  bool after_semicolon = true;  // the first item, or one after ';', must start a spec
  while (true) {
    const std::size_t end = list.find_first_of(",;", start);
    const std::string_view item = trimmed(list.substr(start, end == std::string_view::npos ? end : end - start));
    if (item.empty()) bad_list("it has an empty item: separate laws by one ',' or ';'");
    if (is_parameter_item(item)) {
      if (out.empty()) bad_list("it starts with the parameter " + quoted(item) + ": a law name comes first");
      if (after_semicolon) {
        bad_list("the parameter " + quoted(item) + " follows a ';', which ends a law: join parameters with ','");
      }
      out.back() += "," + std::string(item);
    } else {
      out.emplace_back(item);
    }
    if (end == std::string_view::npos) break;
    after_semicolon = list[end] == ';';
    start = end + 1;
  }
  return out;
}

void check_law_declaration(std::string_view name, const std::vector<LawParameter>& parameters) {
  if (name.empty()) throw std::invalid_argument("a friction law's name is empty");
  if (!valid_name(name)) {
    throw std::invalid_argument("the friction law name " + quoted(name) +
                                " is not a name (letters, digits and . _ + -, starting with a letter or digit)");
  }
  const auto bad = [&](const LawParameter& p, const std::string& why) {
    throw std::invalid_argument("friction law " + std::string(name) + ": parameter " + quoted(p.key) + " " + why);
  };
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    const LawParameter& p = parameters[i];
    if (!valid_key(p.key)) bad(p, "is not a key (letters, digits and _, starting with a letter or _)");
    for (std::size_t j = 0; j < i; ++j) {
      if (parameters[j].key == p.key) bad(p, "is declared twice");
    }
    if (p.doc.empty()) bad(p, "has no description");
    if (p.kind == LawParameter::Kind::choice) {
      if (p.choices.empty()) bad(p, "has no choices");
      for (const auto& c : p.choices) {
        if (!valid_value(c)) bad(p, "has the choice " + quoted(c) + ", which is not a value (no , ; : = or spaces)");
      }
      if (std::find(p.choices.begin(), p.choices.end(), p.default_value) == p.choices.end()) {
        bad(p, "has the default " + quoted(p.default_value) + ", not " + p.rule());
      }
    } else {
      if (std::isnan(p.min) || std::isnan(p.max) || !(p.min <= p.max)) bad(p, "has an empty range " + p.rule());
      if (p.default_value.empty()) {
        if (p.default_doc.empty()) bad(p, "has no default: say what the law does without it (default_doc)");
      } else {
        const auto x = parse_number(p.default_value);
        if (!x || !in_range(p, *x)) bad(p, "has the default " + quoted(p.default_value) + ", not " + p.rule());
      }
    }
  }
}

LawArguments::LawArguments(std::string name, std::vector<LawParameter> parameters)
    : spec_(name), name_(std::move(name)) {
  for (auto& p : parameters) {
    Value v;
    v.has_value = !p.default_value.empty();
    v.text = p.default_value;
    if (p.kind == LawParameter::Kind::number && v.has_value) v.number = parse_number(v.text).value_or(0.0);
    v.parameter = std::move(p);
    values_.push_back(std::move(v));
  }
}

std::string LawArguments::canonical() const {
  std::string out = name_;
  char sep = ':';
  for (const auto& v : values_) {
    if (!v.has_value || !v.given) continue;
    std::string text = v.text;
    if (v.parameter.kind == LawParameter::Kind::number) {
      text = shortest(v.number);
      if (!v.parameter.default_value.empty() && *parse_number(v.parameter.default_value) == v.number) continue;
    } else if (text == v.parameter.default_value) {
      continue;
    }
    out += sep + v.parameter.key + "=" + text;
    sep = ',';
  }
  return out;
}

const LawArguments::Value& LawArguments::find(std::string_view key, LawParameter::Kind kind) const {
  for (const auto& v : values_) {
    if (v.parameter.key == key && v.parameter.kind == kind) return v;
  }
  throw std::logic_error("friction law " + name_ + " declares no " +
                         (kind == LawParameter::Kind::choice ? "choice" : "number") + " parameter " + quoted(key));
}

const std::string& LawArguments::choice(std::string_view key) const { return find(key, LawParameter::Kind::choice).text; }

std::optional<double> LawArguments::number(std::string_view key) const {
  const Value& v = find(key, LawParameter::Kind::number);
  if (!v.has_value) return std::nullopt;
  return v.number;
}

bool LawArguments::given(std::string_view key) const {
  for (const auto& v : values_) {
    if (v.parameter.key == key) return v.given;
  }
  return false;
}

LawArguments bind_law_spec(const ParsedLawSpec& spec, const std::vector<LawParameter>& parameters) {
  LawArguments args(spec.name, parameters);
  args.spec_ = spec.text;
  for (const auto& [key, value] : spec.arguments) {
    auto it = std::find_if(args.values_.begin(), args.values_.end(),
                           [&](const LawArguments::Value& v) { return v.parameter.key == key; });
    if (it == args.values_.end()) {
      bad_spec(spec.text, parameters.empty()
                              ? spec.name + " has no parameters: write " + spec.name + " alone"
                              : spec.name + " has no parameter " + quoted(key) + "; its parameters: " + keys_of(parameters));
    }
    LawArguments::Value& v = *it;
    if (v.given) bad_spec(spec.text, key + " is given twice: give each parameter once");
    const LawParameter& p = v.parameter;
    const auto not_allowed = [&] {
      bad_spec(spec.text, key + " = " + quoted(value) + " is not allowed: " + key + " must be " + p.rule());
    };
    if (p.kind == LawParameter::Kind::choice) {
      if (std::find(p.choices.begin(), p.choices.end(), value) == p.choices.end()) not_allowed();
    } else {
      const auto x = parse_number(value);
      if (!x || !in_range(p, *x)) not_allowed();
      v.number = *x;
    }
    v.given = true;
    v.has_value = true;
    v.text = value;
  }
  return args;
}

std::string law_file_stem(std::string_view spec) {
  std::string out(spec);
  for (char& c : out) {
    if (c == '=') {
      c = '-';
    } else if (!(is_alpha(c) || is_digit(c) || c == '.' || c == '_' || c == '+' || c == '-')) {
      c = '_';
    }
  }
  return out;
}

}  // namespace frictionlab::friction
