// SPDX-License-Identifier: BSL-1.0
// A planted finding for the static analysis (tests/lint): a query whose result a caller
// could drop without a word. lint.tidy.finds_a_planted_finding passes only when clang-tidy
// reports it, so a configuration that silently checks nothing fails.
struct Planted {
  int value() const { return value_; }  // [[nodiscard]] left out on purpose
  int value_ = 0;
};

int main() { return Planted{}.value(); }
