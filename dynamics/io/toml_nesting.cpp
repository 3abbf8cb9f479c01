#include "dynamics/io/toml_nesting.h"

#include <stdexcept>
#include <vector>

namespace frictionlab::dynamics {
namespace {

// Skips the string starting at text[i] (a quote): basic "..." and literal '...', one-line or
// multi-line ("""...""", '''...''', which may end with up to two more quotes). Counts the
// newlines it passes. Returns the index after it (or the end of an unterminated one-line string's
// line, or of the text).
std::size_t skip_string(std::string_view text, std::size_t i, std::size_t& line) {
  const char quote = text[i];
  const bool escapes = quote == '"';
  const std::size_t n = text.size();
  if (i + 2 < n && text[i + 1] == quote && text[i + 2] == quote) {
    std::size_t j = i + 3;
    while (j < n) {
      if (escapes && text[j] == '\\') {
        if (j + 1 < n && text[j + 1] == '\n') ++line;
        j += 2;
        continue;
      }
      if (text[j] == '\n') ++line;
      if (j + 2 < n && text[j] == quote && text[j + 1] == quote && text[j + 2] == quote) {
        j += 3;
        for (int extra = 0; extra < 2 && j < n && text[j] == quote; ++extra) ++j;
        return j;
      }
      ++j;
    }
    return n;
  }
  std::size_t j = i + 1;
  while (j < n && text[j] != '\n') {
    if (escapes && text[j] == '\\') {
      j += 2;
      continue;
    }
    if (text[j] == quote) return j + 1;
    ++j;
  }
  return j < n ? j : n;
}

}  // namespace

TomlNesting toml_nesting(std::string_view text, int stop_above) {
  // What the next token is: a key (or a table header at the start of a top-level line), a value,
  // or the end of a value (a comma, a closing bracket, a comment, the end of the line).
  enum class Expect { key, value, end };
  // An array or inline table being read, and the depth of the key or element that holds it.
  struct Open {
    bool inline_table;
    int depth;
  };
  std::vector<Open> open;
  TomlNesting deepest;
  std::size_t line = 1;
  int header = 0;       // depth of the current [table]
  int key_parts = 1;    // parts of the key being read
  int value_depth = 0;  // depth of the value being read
  Expect expect = Expect::key;
  const auto reach = [&](int depth) {
    if (depth > deepest.depth) deepest = {depth, line};
    return depth > stop_above;
  };
  const std::size_t n = text.size();
  std::size_t i = 0;
  while (i < n) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      ++i;
      if (open.empty()) {
        expect = Expect::key;
        key_parts = 1;
      }
      continue;
    }
    if (c == ' ' || c == '\t' || c == '\r') {
      ++i;
      continue;
    }
    if (c == '#') {
      while (i < n && text[i] != '\n') ++i;
      continue;
    }
    if (c == '"' || c == '\'') {  // a quoted key part, or a string value
      i = skip_string(text, i, line);
      if (expect == Expect::value) expect = Expect::end;
      continue;
    }
    ++i;
    switch (expect) {
      case Expect::key:
        if (c == '[' && open.empty()) {
          // [a.b.c] or [[a.b.c]]: the header's parts, one more for an array of tables.
          int parts = 1;
          if (i < n && text[i] == '[') {
            ++parts;
            ++i;
          }
          while (i < n && text[i] != ']' && text[i] != '\n') {
            if (text[i] == '"' || text[i] == '\'') {
              i = skip_string(text, i, line);
              continue;
            }
            if (text[i] == '.') ++parts;
            ++i;
          }
          header = parts;
          if (reach(header)) return deepest;
          expect = Expect::end;
        } else if (c == '.') {
          ++key_parts;
        } else if (c == '=') {
          value_depth = (open.empty() ? header : open.back().depth) + key_parts;
          if (reach(value_depth)) return deepest;
          key_parts = 1;
          expect = Expect::value;
        } else if (c == '}' && !open.empty() && open.back().inline_table) {  // {} or a trailing comma
          open.pop_back();
          expect = Expect::end;
        }
        break;
      case Expect::value:
        if (c == '[') {
          open.push_back({false, value_depth});
          if (reach(++value_depth)) return deepest;
        } else if (c == '{') {
          open.push_back({true, value_depth});
          expect = Expect::key;
          key_parts = 1;
        } else if (c == ']' && !open.empty() && !open.back().inline_table) {  // [] or a trailing comma
          open.pop_back();
          expect = Expect::end;
        } else {
          expect = Expect::end;  // a number, a boolean, a date: nothing nests in it
        }
        break;
      case Expect::end:
        if (c == ',' && !open.empty()) {
          if (open.back().inline_table) {
            expect = Expect::key;
            key_parts = 1;
          } else {
            expect = Expect::value;
            value_depth = open.back().depth + 1;
          }
        } else if ((c == ']' || c == '}') && !open.empty() && open.back().inline_table == (c == '}')) {
          open.pop_back();
        }
        break;
    }
  }
  return deepest;
}

void check_toml_nesting(int depth, const std::string& where) {
  if (depth <= kMaxTomlNesting) return;
  throw std::invalid_argument(where + ": nested more than " + std::to_string(kMaxTomlNesting) +
                              " levels deep; frictionlab reads at most " + std::to_string(kMaxTomlNesting) +
                              " (each part of a table name or dotted key, each array and inline table is a level: "
                              "a.b.c = 1 is 3)");
}

void check_toml_nesting(std::string_view text, const std::string& source) {
  const TomlNesting n = toml_nesting(text);
  check_toml_nesting(n.depth, source + ":" + std::to_string(n.line));
}

}  // namespace frictionlab::dynamics
