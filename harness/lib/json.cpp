#include "json.h"

#include <cctype>
#include <cstdio>
#include <cstdlib>

#include "io.h"

namespace bvb::json {

const Value *Value::get(const std::string &key) const {
  for (const auto &kv : obj)
    if (kv.first == key) return &kv.second;
  return nullptr;
}

namespace {

struct Parser {
  const std::string &t;
  const std::string &name;
  size_t i = 0;
  int depth = 0;

  [[noreturn]] void fail(const std::string &what) {
    throw InputError(name + ": malformed JSON at byte " + std::to_string(i) + ": " + what);
  }
  void ws() {
    while (i < t.size() && std::isspace(uint8_t(t[i]))) ++i;
  }
  bool eat(char c) {
    ws();
    if (i < t.size() && t[i] == c) {
      ++i;
      return true;
    }
    return false;
  }
  void expect(char c) {
    if (!eat(c)) fail(std::string("expected '") + c + "'");
  }
  std::string string() {
    ws();
    if (i >= t.size() || t[i] != '"') fail("expected a string");
    ++i;
    std::string s;
    while (i < t.size() && t[i] != '"') {
      char c = t[i++];
      if (c == '\\') {
        if (i >= t.size()) fail("unfinished escape");
        char e = t[i++];
        switch (e) {
          case 'n': s += '\n'; break;
          case 't': s += '\t'; break;
          case 'r': s += '\r'; break;
          case 'b': s += '\b'; break;
          case 'f': s += '\f'; break;
          case 'u': {
            if (i + 4 > t.size()) fail("short \\u escape");
            unsigned v = unsigned(std::strtoul(t.substr(i, 4).c_str(), nullptr, 16));
            i += 4;
            if (v < 0x80) s += char(v);
            else if (v < 0x800) { s += char(0xC0 | (v >> 6)); s += char(0x80 | (v & 0x3F)); }
            else { s += char(0xE0 | (v >> 12)); s += char(0x80 | ((v >> 6) & 0x3F)); s += char(0x80 | (v & 0x3F)); }
            break;
          }
          default: s += e;
        }
      } else {
        if (uint8_t(c) < 0x20) fail("control character in string");
        s += c;
      }
    }
    if (i >= t.size()) fail("unterminated string");
    ++i;
    return s;
  }
  Value value() {
    if (++depth > 64) fail("nested too deeply");
    ws();
    Value v;
    if (i >= t.size()) fail("unexpected end");
    char c = t[i];
    if (c == '{') {
      ++i;
      v.type = Value::Object;
      if (!eat('}')) {
        do {
          std::string k = string();
          expect(':');
          v.obj.emplace_back(k, value());
        } while (eat(','));
        expect('}');
      }
    } else if (c == '[') {
      ++i;
      v.type = Value::Array;
      if (!eat(']')) {
        do v.arr.push_back(value());
        while (eat(','));
        expect(']');
      }
    } else if (c == '"') {
      v.type = Value::String;
      v.str = string();
    } else if (t.compare(i, 4, "true") == 0) {
      v.type = Value::Bool, v.b = true, i += 4;
    } else if (t.compare(i, 5, "false") == 0) {
      v.type = Value::Bool, i += 5;
    } else if (t.compare(i, 4, "null") == 0) {
      i += 4;
    } else if (c == '-' || std::isdigit(uint8_t(c))) {
      const char *start = t.c_str() + i;
      char *end = nullptr;
      v.type = Value::Number;
      v.num = std::strtod(start, &end);
      if (end == start) fail("bad number");
      i += size_t(end - start);
    } else {
      fail("unexpected character");
    }
    --depth;
    return v;
  }
};

}  // namespace

Value parse(const std::string &text, const std::string &name) {
  Parser p{text, name};
  Value v = p.value();
  p.ws();
  if (p.i != text.size()) p.fail("trailing characters");
  return v;
}

std::string quote(const std::string &s) {
  std::string o = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') o += '\\', o += c;
    else if (c == '\n') o += "\\n";
    else if (uint8_t(c) < 0x20) {
      char b[8];
      std::snprintf(b, sizeof b, "\\u%04x", c);
      o += b;
    } else o += c;
  }
  return o + "\"";
}

}  // namespace bvb::json
