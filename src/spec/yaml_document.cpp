#include "yaml_document.hpp"

#include "yaml_quotes.hpp"
#include <vector>

namespace pbrfit::spec {
namespace {

std::vector<YAML::Node> parse_documents(const YamlSource& source) {
  try {
    return YAML::LoadAll(source.text());
  } catch (const YAML::Exception& error) {
    throw InputError(source.position(error.mark), "invalid YAML: " + error.msg);
  }
}

}  // namespace

YAML::Node load_root_mapping(const YamlSource& source) {
  const std::vector<YAML::Node> documents = parse_documents(source);
  if (documents.empty() || (documents.size() == 1 && source.is_blank(documents.front()))) {
    throw InputError(SourcePosition{source.file(), 0, 0}, "the job file is empty");
  }
  if (documents.size() > 1) {
    throw InputError(source.position(documents[1].Mark()), "a job file must hold a single YAML document");
  }
  const YAML::Node& root = documents.front();
  reject_unclosed_quotes(root, source);
  if (!root.IsMap()) {
    throw InputError(source.position(root.Mark()), "a job file must be a mapping of keys to values");
  }
  return root;
}

}  // namespace pbrfit::spec
