#include "pbrfit/jobs/brdf/tree_bytes.hpp"

#include <cmath>
#include <stdexcept>

namespace pbrfit::jobs::brdf {
namespace {

[[noreturn]] void reject(const ByteReader& in, const char* what) { throw ByteFormatError(in.offset(), what); }

std::uint64_t count(ByteReader& in, std::size_t bytes_each) {
  const std::uint64_t n = in.get_varint();
  if (n > in.remaining() / bytes_each) reject(in, "a count exceeds the data");
  return n;
}

}  // namespace

void write_tree(ByteWriter& out, const gp::SyntaxTree& tree) {
  out.put_varint(tree.size());
  for (const auto& node : tree.nodes()) {
    out.put(std::uint8_t(node.kind));
    if (node.kind == gp::NodeKind::operation) out.put(std::uint8_t(node.op));
    if (node.kind == gp::NodeKind::input || node.kind == gp::NodeKind::parameter) out.put_varint(node.index);
    if (node.kind == gp::NodeKind::constant) out.put(node.value);
  }
}

gp::SyntaxTree read_tree(ByteReader& in, std::size_t inputs, std::size_t parameters) {
  std::vector<gp::SyntaxNode> nodes(count(in, 2));
  for (auto& node : nodes) {
    const auto kind = in.get<std::uint8_t>();
    if (kind > 3) reject(in, "an unknown node kind");
    node.kind = gp::NodeKind(kind);
    if (node.kind == gp::NodeKind::operation) {
      const auto op = in.get<std::uint8_t>();
      if (!gp::is_valid_opcode(op) || op == 0) reject(in, "an unknown operator");
      node.op = gp::Opcode(op);
    } else if (node.kind == gp::NodeKind::constant) {
      node.value = in.get<double>();
      if (!std::isfinite(node.value)) reject(in, "a constant that is not finite");
    } else {
      const auto index = in.get_varint();
      if (index >= (node.kind == gp::NodeKind::input ? inputs : parameters)) reject(in, "an input or parameter out of range");
      node.index = std::uint16_t(index);
    }
  }
  try {
    return gp::SyntaxTree(std::move(nodes));
  } catch (const std::invalid_argument& e) {
    reject(in, "a malformed tree");
  }
}

gp::Edit read_edit(ByteReader& in) {
  const auto kind = in.get<std::uint8_t>();
  if (kind > 3) reject(in, "an unknown edit");
  const auto first = in.get<std::uint32_t>();
  return {gp::EditKind(kind), first, in.get<std::uint32_t>()};
}

}  // namespace pbrfit::jobs::brdf
