#include "chain_workload.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <cstdio>
#include <cstring>
#include <thread>

#include "pbrfit/core/error.hpp"

namespace pbrfit::testing {

namespace {

std::vector<double> iota(std::uint64_t n) {
  std::vector<double> v(n);
  for (std::uint64_t i = 0; i < n; ++i) v[i] = double(i);
  return v;
}

// Values as exact doubles: 53 bits of a 64-bit value.
double as_double(std::uint64_t v) { return double(v >> 11); }

}  // namespace

store::ResultLayout ChainWorkload::layout() const {
  using store::ValueType;
  store::Group g;
  g.name = "chain";
  g.description = "synthetic chained stages (runtime tests)";
  g.axes = {{"stage", iota(settings_.stages), "stage"}, {"item", iota(settings_.items), "item"}};
  g.tables = {{"value", {"stage", "item"}, "the item's value (top 53 bits)"},
              {"random", {"stage", "item"}, "the item's first random number (top 53 bits)"},
              {"log", {"row"}, "records appended by items, in item order", ValueType::f64,
               {{"stage", ValueType::u32, ""}, {"item", ValueType::u64, ""}, {"value", ValueType::f64, ""},
                {"note", ValueType::text, ""}},
               true}};
  return {{g}};
}

ChainWorkload::Result ChainWorkload::decode(const Bytes& bytes) {
  if (bytes.size() < 2 * sizeof(std::uint64_t)) throw RunError("chain result too short");
  ByteReader in(bytes);
  return {in.get<std::uint64_t>(), in.get<std::uint64_t>()};
}

void ChainWorkload::report(std::uint32_t stage) const {
  std::error_code error;
  const auto size = [&](const std::string& path) {
    const auto bytes = std::filesystem::file_size(path, error);
    return error ? 0 : bytes;
  };
  std::fprintf(stderr, "report: stage %u peak_rss_kib %ld checkpoint_bytes %llu journal_bytes %llu\n", stage,
               peak_rss_kib(), static_cast<unsigned long long>(size(settings_.output + ".checkpoint")),
               static_cast<unsigned long long>(size(settings_.output + ".journal")));
}

long peak_rss_kib() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stol(line.substr(6));
  return 0;
}

void ChainWorkload::maybe_raise(std::uint32_t stage, std::uint64_t collected) const {
  if (settings_.signal != 0 && stage == settings_.signal_stage && collected == settings_.signal_after)
    std::raise(settings_.signal);
}

Bytes ChainWorkload::stage_context(std::uint32_t stage, const ItemResults& kept) const {
  maybe_raise(stage, 0);
  if (std::find(settings_.report_stages.begin(), settings_.report_stages.end(), stage) != settings_.report_stages.end())
    report(stage);
  std::uint64_t count = 0, sum = 0;
  for (const auto& [id, result] : kept) {
    if (stage == 0 || id.stage != previous(stage)) continue;
    ++count;
    sum += decode(result).value;
  }
  ByteWriter out;
  out.put(count);
  out.put(sum);
  return out.take();
}

Bytes ChainWorkload::item_input(std::uint32_t stage, std::uint64_t item, const ItemResults& kept) const {
  ByteWriter out;
  if (stage == 0) return out.take();
  const auto neighbour = (item + settings_.items - 1) % settings_.items;
  out.put(decode(kept.at({previous(stage), item})).value);
  out.put(decode(kept.at({previous(stage), neighbour})).value);
  return out.take();
}

Bytes ChainWorkload::compute(const runtime::ItemTask& task) const {
  ByteReader context(task.context);
  const auto count = context.get<std::uint64_t>();
  const auto sum = context.get<std::uint64_t>();
  if (task.id.stage > 0 && count != settings_.items)
    throw RunError("stage " + std::to_string(task.id.stage) + " context built from " + std::to_string(count) + " of " +
                   std::to_string(settings_.items) + " results of the stage before");
  if (task.id.stage == settings_.fail_stage && task.id.item == settings_.fail_item) throw RunError("injected failure");
  std::uint64_t own = 0, neighbour = 0;
  if (task.id.stage > 0) {
    ByteReader input(task.input);
    own = input.get<std::uint64_t>();
    neighbour = input.get<std::uint64_t>();
  }
  auto random = task.random();
  const std::uint64_t r = random.next_u64();
  const auto spin = std::chrono::microseconds(settings_.spin_microseconds * (task.id.item * 7 % 5));
  const auto until = std::chrono::steady_clock::now() + spin;
  while (std::chrono::steady_clock::now() < until) std::this_thread::yield();
  const std::uint64_t head[2] = {mix64(sum ^ mix64(own * 3 + neighbour * 5) ^ r ^ task.id.item), r};
  Bytes bytes(std::max(settings_.result_bytes, sizeof head), std::byte(task.id.item & 0xff));
  std::memcpy(bytes.data(), head, sizeof head);
  return bytes;
}

std::vector<store::Block> ChainWorkload::blocks(WorkItemId id, const Bytes& bytes) const {
  const Result r = decode(bytes);
  std::vector<store::Block> out = {{"chain", "value", {id.stage, id.item}, {1, 1}, {as_double(r.value)}},
                                   {"chain", "random", {id.stage, id.item}, {1, 1}, {as_double(r.random)}}};
  const std::uint64_t rows = settings_.log_rows ? id.item % 3 : 0;
  if (rows == 0) return out;
  store::Block log{"chain", "log", {0}, {rows}, {}, {}};
  for (std::uint64_t k = 0; k < rows; ++k) {
    log.values.insert(log.values.end(), {id.stage, id.item, as_double(r.value) + double(k)});
    log.texts.push_back("s" + std::to_string(id.stage) + "i" + std::to_string(id.item) + "k" + std::to_string(k));
  }
  out.push_back(std::move(log));
  return out;
}

void ChainWorkload::fold_summary(Bytes& summary, WorkItemId id, const Bytes& result) const {
  auto s = runtime::summary_as<Summary>(summary);
  ++s.results;
  s.xor_of_values ^= decode(result).value;
  if (id.stage == settings_.signal_stage) ++s.results_in_signal_stage;
  runtime::store_summary(summary, s);
  if (id.stage == settings_.signal_stage) maybe_raise(id.stage, s.results_in_signal_stage);
}

std::string ChainWorkload::headline(const Bytes& summary) const {
  const auto s = runtime::summary_as<Summary>(summary);
  char text[96];
  std::snprintf(text, sizeof text, "%llu results, xor %016llx", static_cast<unsigned long long>(s.results),
                static_cast<unsigned long long>(s.xor_of_values));
  return text;
}

}  // namespace pbrfit::testing
