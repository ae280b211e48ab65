#pragma once
// The text a child process answers its parent in (forked_items.hpp): numbers in hexadecimal floating
// point, so every double comes back bit for bit (NaN and infinities included), and strings prefixed
// with their size, so any byte may appear in them.

#include <cstdint>
#include <string>
#include <string_view>

namespace ifar::scenarios {

class AnswerWriter {
 public:
  void number(double value);
  void integer(std::int64_t value);
  void flag(bool value) { integer(value ? 1 : 0); }
  void text(std::string_view value);
  // One name for every kind, so one field list can drive a writer and a reader (result_row.cpp).
  void field(double value) { number(value); }
  void field(int value) { integer(value); }
  void field(bool value) { flag(value); }
  void field(const std::string& value) { text(value); }
  const std::string& answer() const { return answer_; }

 private:
  std::string answer_;
};

/// Reads what an AnswerWriter wrote, in the same order. Each read returns false (and reads nothing
/// more) once the answer does not hold what is asked for.
class AnswerReader {
 public:
  /// Reads `answer` in place: it must outlive the reader.
  explicit AnswerReader(std::string_view answer) : rest_(answer) {}
  bool number(double& value);
  bool integer(std::int64_t& value);
  bool flag(bool& value);
  bool text(std::string& value);
  /// As AnswerWriter::field. An integer outside int's range is a failed read.
  bool field(double& value) { return number(value); }
  bool field(int& value);
  bool field(bool& value) { return flag(value); }
  bool field(std::string& value) { return text(value); }
  /// True when every byte was read and no read failed.
  bool complete() const { return ok_ && rest_.empty(); }

 private:
  bool token(std::string& value);
  std::string_view rest_;
  bool ok_ = true;
};

}  // namespace ifar::scenarios
