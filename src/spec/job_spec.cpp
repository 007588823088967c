#include "pbrfit/spec/job_spec.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

#include "common_keys.hpp"
#include "job_file_text.hpp"
#include "message_text.hpp"
#include "yaml_document.hpp"
#include "yaml_validation.hpp"

namespace pbrfit::spec {
namespace {

struct KindKey {
  std::string name;
  SourcePosition where;  // of the value
};

KindKey read_kind(const YAML::Node& root, const KindCatalogue& kinds, const YamlSource& source) {
  for (const auto& pair : root) {
    if (!pair.first.IsScalar() || pair.first.Scalar() != "kind") continue;
    Field kind_field;
    kind_field.name = "kind";
    kind_field.type = FieldType::choice;
    kind_field.choices = kinds.names;
    const Section::Entry kind = validate_value(kind_field, pair.first, pair.second, source);
    return KindKey{std::get<std::string>(kind.value), kind.where};
  }
  throw InputError(source.position(root.Mark()), "missing required key 'kind' in 'job'");
}

// A section named after a kind must be the job's own kind's section.
void check_kind_sections(const YAML::Node& root, const KindKey& kind, const KindCatalogue& kinds,
                         const YamlSource& source) {
  bool has_own_section = false;
  for (const auto& pair : root) {
    if (!pair.first.IsScalar()) continue;
    const std::string& key = pair.first.Scalar();
    if (key == kind.name) {
      has_own_section = true;
    } else if (std::ranges::find(kinds.names, key) != kinds.names.end() && !common_schema().find(key)) {
      throw InputError(source.position(pair.first.Mark()),
                       "section " + quote(key) + " does not belong to a job of kind " + quote(kind.name));
    }
  }
  if (!has_own_section) {
    throw InputError(kind.where,
                     "missing required section " + quote(kind.name) + " for kind " + quote(kind.name));
  }
}

Schema job_schema(const std::string& kind, const KindCatalogue& kinds) {
  Schema schema = common_schema();
  schema.section(kind, kinds.schema_for(kind), "The settings of a " + kind + " job.").require();
  return schema;
}

}  // namespace

JobSpec parse_job_text(const std::string& text, const std::string& file, const KindCatalogue& kinds) {
  const YamlSource source(text, file);
  const YAML::Node root = load_root_mapping(source);
  reject_duplicate_keys(root, "", source);
  const KindKey kind = read_kind(root, kinds, source);
  check_kind_sections(root, kind, kinds, source);
  const Section job = validate_mapping(root, job_schema(kind.name, kinds), "", source);

  JobSpec spec;
  spec.file = file;
  spec.text = text;
  read_common_keys(job, spec);
  spec.kind_section = job.get_section(kind.name);
  return spec;
}

JobSpec load_job_file(const std::string& path, const KindCatalogue& kinds) {
  return parse_job_text(read_job_file_text(path), path, kinds);
}

}  // namespace pbrfit::spec
