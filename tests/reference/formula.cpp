// The slide's notation, evaluated (formula.h): a recursive-descent parser over the text's tokens.
#include "formula.h"

#include <cctype>
#include <stdexcept>
#include <vector>

namespace a6::test {
namespace {

const std::string kDot = "·", kSquare = "²", kTranspose = "ᵀ";

struct Token {
  enum Kind { Number, Symbol, Operator, End } kind = End;
  std::string text;
};

std::vector<Token> tokenize(const std::string& s) {
  std::vector<Token> out;
  for (std::size_t i = 0; i < s.size();) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (std::isspace(c)) {
      ++i;
    } else if (std::isdigit(c) || c == '.') {
      std::size_t j = i;
      while (j < s.size() && (std::isdigit(static_cast<unsigned char>(s[j])) || s[j] == '.')) ++j;
      out.push_back({Token::Number, s.substr(i, j - i)});
      i = j;
    } else if (std::isalpha(c)) {
      std::size_t j = i;
      while (j < s.size() && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '_')) ++j;
      out.push_back({Token::Symbol, s.substr(i, j - i)});
      i = j;
    } else {
      bool matched = false;
      for (const std::string& op : {kDot, kSquare, kTranspose}) {
        if (s.compare(i, op.size(), op) == 0) {
          out.push_back({Token::Operator, op});
          i += op.size(), matched = true;
          break;
        }
      }
      if (matched) continue;
      if (std::string("+-*/(),|").find(s[i]) == std::string::npos)
        throw std::invalid_argument("cannot read '" + s.substr(i, 3) + "' in \"" + s + "\"");
      out.push_back({Token::Operator, std::string(1, s[i++])});
    }
  }
  out.push_back({Token::End, ""});
  return out;
}

bool isScalar(const Value& v) { return v.rows() == 1 && v.cols() == 1; }

Value product(const Value& a, const Value& b) {
  if (isScalar(a)) return a(0, 0) * b;
  if (isScalar(b)) return b(0, 0) * a;
  if (a.cols() != b.rows()) throw std::invalid_argument("a product of mismatched shapes");
  return a * b;
}

Value sumOf(const Value& a, const Value& b, double sign) {
  if (a.rows() != b.rows() || a.cols() != b.cols())
    throw std::invalid_argument("a sum of mismatched shapes");
  return a + sign * b;
}

class Parser {
 public:
  Parser(const std::string& text, const Bindings& bindings)
      : text_(text), tokens_(tokenize(text)), bindings_(bindings) {}

  Value parse() {
    const Value v = expression();
    if (peek().kind != Token::End) fail("unexpected '" + peek().text + "'");
    return v;
  }

 private:
  const Token& peek() const { return tokens_[at_]; }
  bool accept(const std::string& op) {
    if (peek().kind != Token::Operator || peek().text != op) return false;
    ++at_;
    return true;
  }
  [[noreturn]] void fail(const std::string& why) const {
    throw std::invalid_argument(why + " in \"" + text_ + "\"");
  }

  Value expression() {
    Value v = term();
    for (;;) {
      if (accept("+")) {
        v = sumOf(v, term(), 1);
      } else if (accept("-")) {
        v = sumOf(v, term(), -1);
      } else {
        return v;
      }
    }
  }

  // Whether the next token starts a factor multiplied by juxtaposition ("ks (l - l0) e").
  bool startsFactor() const {
    const Token& t = peek();
    if (t.kind == Token::Number || t.kind == Token::Symbol) return true;
    return t.kind == Token::Operator && (t.text == "(" || (t.text == "|" && absDepth_ == 0));
  }

  Value term() {
    Value v = factor();
    for (;;) {
      if (accept("*")) {
        v = product(v, factor());
      } else if (accept("/")) {
        const Value d = factor();
        if (!isScalar(d)) fail("a division by a vector or matrix");
        v = v / d(0, 0);
      } else if (accept(kDot)) {
        const Value w = factor();
        if (v.cols() != 1 || w.cols() != 1 || v.rows() != w.rows()) fail("a dot of non-vectors");
        v = v.transpose() * w;
      } else if (startsFactor()) {
        v = product(v, factor());
      } else {
        return v;
      }
    }
  }

  Value factor() {
    if (accept("-")) return -factor();
    if (accept("+")) return factor();
    Value v = atom();
    for (;;) {
      if (accept(kTranspose)) {
        v = v.transpose().eval();
      } else if (accept(kSquare)) {
        v = isScalar(v) ? Value(v * v) : scalar(v.squaredNorm());
      } else {
        return v;
      }
    }
  }

  Value atom() {
    const Token t = peek();
    ++at_;
    if (t.kind == Token::Number) return scalar(std::stod(t.text));
    if (t.kind == Token::Symbol) {
      const auto it = bindings_.find(t.text);
      if (it == bindings_.end()) fail("the symbol " + t.text + " has no value");
      return it->second;
    }
    if (t.text == "(") return parenthesised();
    if (t.text == "|") {
      ++absDepth_;
      const Value v = expression();
      --absDepth_;
      if (!accept("|")) fail("an unclosed |");
      return scalar(v.norm());
    }
    fail("unexpected '" + t.text + "'");
  }

  // (x) or the vector (a, b).
  Value parenthesised() {
    const int outer = absDepth_;
    absDepth_ = 0;
    Value v = expression();
    if (accept(",")) {
      const Value y = expression();
      if (!isScalar(v) || !isScalar(y)) fail("a vector of non-numbers");
      v = Eigen::Vector2d(v(0, 0), y(0, 0));
    }
    absDepth_ = outer;
    if (!accept(")")) fail("an unclosed (");
    return v;
  }

  std::string text_;
  std::vector<Token> tokens_;
  const Bindings& bindings_;
  std::size_t at_ = 0;
  int absDepth_ = 0;
};

}  // namespace

Value evaluateFormula(const std::string& text, const Bindings& bindings) {
  // An update, "v += f / m dt": the symbol's value plus the right side's.
  const std::size_t update = text.find("+=");
  if (update == std::string::npos) return Parser(text, bindings).parse();
  const Value before = Parser(text.substr(0, update), bindings).parse();
  const Value change = Parser(text.substr(update + 2), bindings).parse();
  if (before.rows() != change.rows() || before.cols() != change.cols())
    throw std::invalid_argument("an update of mismatched shapes in \"" + text + "\"");
  return before + change;
}

std::string withoutBlanks(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (!std::isspace(static_cast<unsigned char>(c))) out += c;
  }
  return out;
}

}  // namespace a6::test
