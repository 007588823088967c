#include "yaml_document.hpp"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/parser.h>

#include "yaml_quotes.hpp"
#include <sstream>
#include <string>
#include <vector>

namespace pbrfit::spec {
namespace {

// Where each document's first node starts (its node's Mark()), for the documents the parser has read.
class DocumentMarks : public YAML::EventHandler {
 public:
  std::vector<YAML::Mark> first_nodes;

  void OnDocumentStart(const YAML::Mark&) override { in_document_ = false; }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t) override { node(mark); }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t) override { node(mark); }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t, const std::string&) override { node(mark); }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
    node(mark);
  }
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
    node(mark);
  }
  void OnMapEnd() override {}

 private:
  void node(const YAML::Mark& mark) {
    if (!in_document_) first_nodes.push_back(mark);
    in_document_ = true;
  }
  bool in_document_ = false;
};

struct Documents {
  std::size_t count = 0;  // 0, 1 or 2 (two or more)
  YAML::Node first;
  YAML::Mark second;  // where the second document starts, when there is one
};

// The documents of a text, counted by the parser up to two and the first loaded alone. Not YAML::LoadAll:
// Debian 12's yaml-cpp 0.7 loops in it for ever, allocating without bound, on texts where its parser
// stops consuming tokens (a stray comma after a flow collection, "[0],"; jbeder/yaml-cpp#1040, fixed in
// later versions by #1319), and counting stops at the second document whatever the parser does.
Documents parse_documents(const YamlSource& source) {
  try {
    Documents d;
    std::istringstream text(source.text());
    YAML::Parser parser(text);
    DocumentMarks marks;
    while (d.count < 2 && parser.HandleNextDocument(marks)) ++d.count;
    if (d.count == 0) return d;
    d.first = YAML::Load(source.text());
    if (d.count == 2) d.second = marks.first_nodes.size() >= 2 ? marks.first_nodes[1] : YAML::Mark();
    return d;
  } catch (const YAML::Exception& error) {
    throw InputError(source.position(error.mark), "invalid YAML: " + error.msg);
  }
}

}  // namespace

YAML::Node load_root_mapping(const YamlSource& source) {
  const Documents documents = parse_documents(source);
  if (documents.count == 0 || (documents.count == 1 && source.is_blank(documents.first))) {
    throw InputError(SourcePosition{source.file(), 0, 0}, "the job file is empty");
  }
  if (documents.count > 1) {
    throw InputError(source.position(documents.second), "a job file must hold a single YAML document");
  }
  const YAML::Node& root = documents.first;
  reject_unclosed_quotes(root, source);
  if (!root.IsMap()) {
    throw InputError(source.position(root.Mark()), "a job file must be a mapping of keys to values");
  }
  return root;
}

}  // namespace pbrfit::spec
