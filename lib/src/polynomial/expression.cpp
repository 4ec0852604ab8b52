#include "implicitizer/polynomial/expression.hpp"

#include <set>

#include "implicitizer/core/errors.hpp"

namespace implicitizer {

namespace {

struct Token {
  enum class Kind { number, identifier, plus, minus, star, slash, caret, lparen, rparen, end };
  Kind kind = Kind::end;
  std::size_t start = 0;  // first character
  std::size_t end = 0;    // one past the last character
  std::string_view text;
};

// ASCII only, whatever the C locale says: the contract's identifiers are
// [A-Za-z_][A-Za-z0-9_]*, and std::isalpha accepts bytes like 0xE9 under Latin-1 locales.
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_identifier_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool is_identifier_char(char c) { return is_identifier_start(c) || is_digit(c); }

std::string describe(char c) {
  const auto u = static_cast<unsigned char>(c);
  if (u < 0x20 || u >= 0x7f) {
    static const char* hex = "0123456789abcdef";
    return std::string("byte 0x") + hex[u >> 4] + hex[u & 15];
  }
  return std::string("'") + c + "'";
}

class Lexer {
 public:
  Lexer(std::string_view text, const ParseParams& limits) : text_(text), limits_(limits) {}

  Token next() {
    while (pos_ < text_.size() &&
           (text_[pos_] == ' ' || text_[pos_] == '\t' || text_[pos_] == '\n' || text_[pos_] == '\r')) {
      ++pos_;
    }
    Token t;
    t.start = pos_;
    if (pos_ == text_.size()) {
      t.kind = Token::Kind::end;
      t.end = pos_;
      return t;
    }
    const char c = text_[pos_];
    if (is_digit(c) || (c == '.' && pos_ + 1 < text_.size() && is_digit(text_[pos_ + 1]))) {
      lex_number(t);
    } else if (is_identifier_start(c)) {
      std::size_t p = pos_;
      while (p < text_.size() && is_identifier_char(text_[p])) ++p;
      if (p - pos_ > limits_.max_identifier) {
        throw InputError("identifier_too_long",
                         "identifier longer than " + std::to_string(limits_.max_identifier) + " characters", pos_);
      }
      t.kind = Token::Kind::identifier;
      pos_ = p;
    } else {
      switch (c) {
        case '+':
          t.kind = Token::Kind::plus;
          break;
        case '-':
          t.kind = Token::Kind::minus;
          break;
        case '*':
          if (pos_ + 1 < text_.size() && text_[pos_ + 1] == '*') {
            t.kind = Token::Kind::caret;
            ++pos_;
          } else {
            t.kind = Token::Kind::star;
          }
          break;
        case '/':
          t.kind = Token::Kind::slash;
          break;
        case '^':
          t.kind = Token::Kind::caret;
          break;
        case '(':
          t.kind = Token::Kind::lparen;
          break;
        case ')':
          t.kind = Token::Kind::rparen;
          break;
        default:
          throw InputError("unexpected_character", "unexpected character " + describe(c), pos_);
      }
      ++pos_;
    }
    t.end = pos_;
    t.text = text_.substr(t.start, t.end - t.start);
    return t;
  }

 private:
  // digits [. digits] [(e|E) [+-] digits]; the exponent part is taken only when a
  // digit follows, so that `2e` and `2ex` read as 2·e and 2·ex.
  void lex_number(Token& t) {
    std::size_t p = pos_;
    while (p < text_.size() && is_digit(text_[p])) ++p;
    if (p < text_.size() && text_[p] == '.') {
      if (p + 1 < text_.size() && is_digit(text_[p + 1])) {
        ++p;
        while (p < text_.size() && is_digit(text_[p])) ++p;
      } else {
        throw InputError("unexpected_character", "a decimal point must be followed by a digit", p);
      }
    }
    if (p < text_.size() && (text_[p] == 'e' || text_[p] == 'E')) {
      std::size_t q = p + 1;
      if (q < text_.size() && (text_[q] == '+' || text_[q] == '-')) ++q;
      if (q < text_.size() && is_digit(text_[q])) {
        p = q;
        while (p < text_.size() && is_digit(text_[p])) ++p;
      }
    }
    t.kind = Token::Kind::number;
    pos_ = p;
  }

  std::string_view text_;
  const ParseParams& limits_;
  std::size_t pos_ = 0;
};

// Exact value of a decimal literal: mantissa digits over a power of ten.
Rational number_value(std::string_view s, std::size_t position) {
  std::string digits;
  long scale = 0;  // value = digits * 10^scale
  std::size_t i = 0;
  for (; i < s.size() && is_digit(s[i]); ++i) digits += s[i];
  if (i < s.size() && s[i] == '.') {
    for (++i; i < s.size() && is_digit(s[i]); ++i) {
      digits += s[i];
      --scale;
    }
  }
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    bool negative = false;
    if (s[i] == '+' || s[i] == '-') negative = s[i++] == '-';
    std::string_view ex = s.substr(i);
    if (ex.size() > 6) throw InputError("number_too_large", "decimal exponent too large", position);
    long e = std::stol(std::string(ex));
    if (e > 100000) throw InputError("number_too_large", "decimal exponent too large", position);
    scale += negative ? -e : e;
  }
  if (digits.empty()) digits = "0";
  mpz_class mantissa(digits, 10);
  mpz_class power;
  mpz_ui_pow_ui(power.get_mpz_t(), 10, static_cast<unsigned long>(scale < 0 ? -scale : scale));
  mpq_class q = scale < 0 ? mpq_class(mantissa, power) : mpq_class(mantissa * power);
  q.canonicalize();
  return to_rational(q);
}

std::unique_ptr<Expression> make(Expression::Kind kind, std::size_t position) {
  auto e = std::make_unique<Expression>();
  e->kind = kind;
  e->position = position;
  return e;
}

std::unique_ptr<Expression> wrap(Expression::Kind kind, std::size_t position, std::unique_ptr<Expression> child) {
  auto e = make(kind, position);
  e->children.push_back(std::move(child));
  return e;
}

// Recursive descent over:
//   sum     := product (('+'|'-') product)*
//   product := unary (('*'|'/') unary)*
//   unary   := ('-'|'+') unary | power
//   power   := atom [('^'|'**') INTEGER]
//   atom    := NUMBER [IDENTIFIER directly after it: a product] | IDENTIFIER | call | '(' sum ')'
//   call    := IDENTIFIER '(' sum ')'
// so `^` binds tighter than unary minus and than `*` and `/`.
class Parser {
 public:
  Parser(std::string_view text, const ParseParams& limits) : lexer_(text, limits), limits_(limits) { advance(); }

  std::unique_ptr<Expression> parse() {
    if (current_.kind == Token::Kind::end) throw InputError("empty_input", "empty expression", 0);
    auto e = sum();
    if (current_.kind == Token::Kind::rparen) {
      throw InputError("unexpected_token", "')' without a matching '('", current_.start);
    }
    if (current_.kind != Token::Kind::end) throw missing_operator();
    return e;
  }

 private:
  void advance() { current_ = lexer_.next(); }

  InputError missing_operator() const {
    return InputError("missing_operator",
                      "expected an operator before '" + std::string(current_.text) +
                          "' (write products with '*'; only a number may stand directly before a name)",
                      current_.start);
  }

  struct DepthGuard {
    DepthGuard(std::size_t& depth, std::size_t max, std::size_t position) : depth_(depth) {
      if (++depth_ > max) throw InputError("nesting_too_deep", "expression nested too deeply", position);
    }
    ~DepthGuard() { --depth_; }
    std::size_t& depth_;
  };

  std::unique_ptr<Expression> sum() {
    auto first = product();
    if (current_.kind != Token::Kind::plus && current_.kind != Token::Kind::minus) return first;
    auto node = make(Expression::Kind::sum, first->position);
    node->children.push_back(std::move(first));
    while (current_.kind == Token::Kind::plus || current_.kind == Token::Kind::minus) {
      const bool minus = current_.kind == Token::Kind::minus;
      const std::size_t at = current_.start;
      advance();
      node->children.push_back(minus ? wrap(Expression::Kind::negate, at, product()) : product());
    }
    return node;
  }

  std::unique_ptr<Expression> product() {
    auto first = unary();
    if (current_.kind != Token::Kind::star && current_.kind != Token::Kind::slash) return first;
    auto node = make(Expression::Kind::product, first->position);
    node->children.push_back(std::move(first));
    while (current_.kind == Token::Kind::star || current_.kind == Token::Kind::slash) {
      const bool divide = current_.kind == Token::Kind::slash;
      const std::size_t at = current_.start;
      advance();
      node->children.push_back(divide ? wrap(Expression::Kind::reciprocal, at, unary()) : unary());
    }
    return node;
  }

  std::unique_ptr<Expression> unary() {
    DepthGuard guard(depth_, limits_.max_depth, current_.start);
    if (current_.kind == Token::Kind::minus) {
      const std::size_t at = current_.start;
      advance();
      return wrap(Expression::Kind::negate, at, unary());
    }
    if (current_.kind == Token::Kind::plus) {
      advance();
      return unary();
    }
    return power();
  }

  std::unique_ptr<Expression> power() {
    auto base = atom();
    if (current_.kind != Token::Kind::caret) return base;
    return exponentiate(std::move(base));
  }

  std::unique_ptr<Expression> exponentiate(std::unique_ptr<Expression> base) {
    const std::size_t at = current_.start;
    advance();
    if (current_.kind == Token::Kind::end) throw InputError("unexpected_end", "expected an exponent", current_.start);
    const bool integer_literal =
        current_.kind == Token::Kind::number && current_.text.find_first_not_of("0123456789") == std::string_view::npos;
    if (!integer_literal) {
      throw InputError("exponent_not_integer", "an exponent must be a non-negative integer literal", current_.start);
    }
    // Leading zeros do not make an exponent large (x^0002 is x^2).
    std::string_view digits = current_.text;
    while (digits.size() > 1 && digits.front() == '0') digits.remove_prefix(1);
    if (digits.size() > 9 || std::stoul(std::string(digits)) > limits_.max_exponent) {
      throw InputError("exponent_too_large", "exponent larger than " + std::to_string(limits_.max_exponent),
                       current_.start);
    }
    auto e = make(Expression::Kind::power, at);
    e->exponent = static_cast<unsigned>(std::stoul(std::string(digits)));
    e->children.push_back(std::move(base));
    advance();
    if (current_.kind == Token::Kind::caret) {
      throw InputError("chained_exponent", "chained exponents are ambiguous; use parentheses", current_.start);
    }
    return e;
  }

  std::unique_ptr<Expression> atom() {
    const Token t = current_;
    switch (t.kind) {
      case Token::Kind::number: {
        auto n = make(Expression::Kind::number, t.start);
        n->value = number_value(t.text, t.start);
        advance();
        if (current_.kind == Token::Kind::identifier && current_.start == t.end) {
          // `2x^2` is 2·(x^2): the name takes its own exponent.
          auto juxtaposed = make(Expression::Kind::product, t.start);
          juxtaposed->children.push_back(std::move(n));
          juxtaposed->children.push_back(power());
          return juxtaposed;
        }
        return n;
      }
      case Token::Kind::identifier: {
        auto v = make(Expression::Kind::identifier, t.start);
        v->name = std::string(t.text);
        advance();
        // A name directly before '(' is a call, never a missing '*': `s(t)` was never
        // valid, and naming the function says what is wrong with `sqrt(s)`.
        if (current_.kind == Token::Kind::lparen) return call(std::move(v));
        return v;
      }
      case Token::Kind::lparen:
        return parenthesized(t);
      case Token::Kind::end:
        throw InputError("unexpected_end", "the expression ends where an operand was expected", t.start);
      default:
        throw InputError("unexpected_token", "expected a number, a name or '(' but found '" + std::string(t.text) + "'",
                         t.start);
    }
  }

  // '(' sum ')' with the '(' token `open` current (a copy: advance() replaces current_).
  std::unique_ptr<Expression> parenthesized(const Token open) {
    DepthGuard guard(depth_, limits_.max_depth, open.start);
    advance();
    if (current_.kind == Token::Kind::rparen) {
      throw InputError("unexpected_token", "empty parentheses", current_.start);
    }
    auto inner = sum();
    if (current_.kind != Token::Kind::rparen) {
      if (current_.kind == Token::Kind::end) {
        throw InputError("missing_parenthesis", "'(' is never closed", open.start);
      }
      throw missing_operator();
    }
    advance();
    return inner;
  }

  // `name` followed by the current '(' token. The name is checked before its argument
  // is read, so that the first error reported is the function's.
  std::unique_ptr<Expression> call(std::unique_ptr<Expression> name) {
    check_function_name(name->name, name->position);
    auto node = make(Expression::Kind::call, name->position);
    node->name = std::move(name->name);
    node->children.push_back(parenthesized(current_));
    return node;
  }

  static void check_function_name(const std::string& name, std::size_t position) {
    static const std::set<std::string, std::less<>> not_rational = {"sqrt", "exp", "log", "ln"};
    if (not_rational.count(name)) {
      throw InputError("function_not_rational",
                       "'" + name +
                           "' has no exact rational form: only cos, sin, tan, cosh, sinh and tanh of integer "
                           "combinations of the parameters can be converted",
                       position);
    }
    if (!is_function_name(name)) {
      throw InputError("unknown_function",
                       "unknown function '" + name +
                           "' (the functions are cos, sin, tan, cosh, sinh, tanh; write a product as '" + name +
                           "*(...)')",
                       position);
    }
  }

  Lexer lexer_;
  const ParseParams& limits_;
  Token current_;
  std::size_t depth_ = 0;
};

void collect(const Expression& e, std::vector<std::string>& out, std::set<std::string>& seen) {
  if (e.kind == Expression::Kind::identifier && seen.insert(e.name).second) out.push_back(e.name);
  for (const auto& c : e.children) collect(*c, out, seen);
}

}  // namespace

std::unique_ptr<Expression> parse_expression(std::string_view text, const ParseParams& limits) {
  if (text.size() > limits.max_length) {
    throw InputError("input_too_long", "expression longer than " + std::to_string(limits.max_length) + " bytes", 0);
  }
  return Parser(text, limits).parse();
}

std::vector<std::string> collect_identifiers(const Expression& e) {
  std::vector<std::string> out;
  std::set<std::string> seen;
  collect(e, out, seen);
  return out;
}

std::vector<std::string> collect_identifiers(const std::vector<std::unique_ptr<Expression>>& expressions) {
  std::vector<std::string> out;
  std::set<std::string> seen;
  for (const auto& e : expressions) collect(*e, out, seen);
  return out;
}

bool is_function_name(std::string_view name) {
  return name == "cos" || name == "sin" || name == "tan" || name == "cosh" || name == "sinh" || name == "tanh";
}

bool is_identifier(std::string_view name, std::size_t max_length) {
  if (name.empty() || name.size() > max_length || !is_identifier_start(name.front())) return false;
  for (char c : name) {
    if (!is_identifier_char(c)) return false;
  }
  return true;
}

}  // namespace implicitizer
