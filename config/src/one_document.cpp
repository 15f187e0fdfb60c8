#include "one_document.hpp"

#include <algorithm>
#include <optional>
#include <sstream>

#include <yaml-cpp/eventhandler.h>

#include "anchorbench/schema/input_error.hpp"

namespace anchorbench::config {
namespace {

using schema::InputError;

// Where a document starts, and where its first value is (the line a user looks at).
class DocumentMarks : public YAML::EventHandler {
 public:
  std::optional<YAML::Mark> start;
  std::optional<YAML::Mark> content;
  void OnDocumentStart(const YAML::Mark& mark) override { start = mark; }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t) override { See(mark); }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t) override { See(mark); }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t, const std::string&) override { See(mark); }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
    See(mark);
  }
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
    See(mark);
  }
  void OnMapEnd() override {}

 private:
  void See(const YAML::Mark& mark) {
    if (!content) content = mark;
  }
};

std::string LineOf(const YAML::Mark& mark) { return std::to_string(mark.line + 1); }

void RefuseNul(const std::string& text, const std::string& source) {
  const std::size_t nul = text.find('\0');
  if (nul == std::string::npos) return;
  const auto lines = std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(nul), '\n');
  throw InputError(source + ":" + std::to_string(1 + lines) + ": a NUL byte: not a text file");
}

// Steps through at most two documents. yaml-cpp's LoadAll loops without end where its parser does
// not advance (a ',' outside a flow collection, found by fuzz_config): a second document that
// starts where the first did is that case, and is a syntax error, not a second document.
void RefuseASecondDocument(const std::string& text, const std::string& source) {
  std::istringstream in(text);
  YAML::Parser parser(in);
  DocumentMarks first;
  if (!parser.HandleNextDocument(first)) return;
  DocumentMarks second;
  if (!parser.HandleNextDocument(second) || !second.start) return;
  if (first.start && second.start->pos == first.start->pos) {
    throw InputError(source + ":" + LineOf(*second.start) +
                     ": YAML syntax error: the reader cannot go past this point (a ',' outside [] or {}?)");
  }
  throw InputError(source + ":" + LineOf(second.content.value_or(*second.start)) +
                   ": a second YAML document (after '---'): a config is one document");
}

}  // namespace

YAML::Node OnlyDocument(const std::string& text, const std::string& source) {
  RefuseNul(text, source);
  RefuseASecondDocument(text, source);
  return YAML::Load(text);
}

}  // namespace anchorbench::config
