#include "resumption.hpp"

#include <set>

#include "pbrfit/core/error.hpp"
#include "pbrfit/store/block_journal.hpp"

namespace pbrfit::runtime {

namespace {

struct Checker {
  const std::string& path;
  const store::CheckpointState& state;
  const Workload& workload;
  const store::BlockCodec& codec;

  [[noreturn]] void reject(const std::string& what) const {
    throw InputError({path}, "invalid checkpoint for this job: " + what);
  }

  static std::string name(WorkItemId id) {
    return "item " + std::to_string(id.item) + " of stage " + std::to_string(id.stage);
  }

  void check_stage() const {
    if (state.stage > workload.stage_count())
      reject("stage " + std::to_string(state.stage) + " (the job has " + std::to_string(workload.stage_count()) + ")");
    std::uint32_t growing = 0;
    for (std::uint32_t t = 0; t < codec.tables().size(); ++t) growing += codec.tables().table(t).growing;
    if (state.rows.size() != growing) reject("row counts for " + std::to_string(state.rows.size()) + " growing tables");
  }

  std::set<std::uint64_t> check_done() const {
    std::set<std::uint64_t> done;
    const std::uint64_t count = state.stage < workload.stage_count() ? workload.item_count(state.stage) : 0;
    for (const auto item : state.done) {
      if (item >= count) reject(name({state.stage, item}) + ", which the job does not have");
      if (!done.insert(item).second) reject(name({state.stage, item}) + " finished twice");
    }
    return done;
  }

  void check_kept(const std::set<std::uint64_t>& done) const {
    for (const auto& [id, result] : state.retained) {
      if (id.stage > state.stage || id.item >= workload.item_count(id.stage)) reject(name(id) + ", which the job does not have");
      if (id.stage == state.stage && !done.contains(id.item)) reject("a kept result of unfinished " + name(id));
      try {
        workload.blocks(id, result);
      } catch (const std::exception& e) {
        reject("the result of " + name(id) + " is malformed: " + e.what());
      }
    }
  }

  void check_appends(const std::set<std::uint64_t>& done) const {
    for (const auto& [item, encoded] : state.appends) {
      if (!done.contains(item)) reject("rows of unfinished " + name({state.stage, item}));
      try {
        ByteReader in(encoded);
        const auto count = in.get<std::uint64_t>();
        for (std::uint64_t i = 0; i < count; ++i) {
          const auto block = codec.decode(in);
          if (!codec.tables().table(codec.tables().find(block.group, block.table)).growing)
            reject("pending rows for the fixed table " + block.group + "/" + block.table);
        }
        if (in.remaining() != 0) reject("trailing data after the rows of " + name({state.stage, item}));
      } catch (const ByteFormatError& e) {
        reject("the rows of " + name({state.stage, item}) + " are malformed: " + e.what());
      }
    }
  }

  void check_summary() const {
    try {
      workload.headline(state.summary);
    } catch (const std::exception& e) {
      reject(std::string("the summary is malformed: ") + e.what());
    }
  }
};

}  // namespace

void check_checkpoint(const std::string& path, const store::CheckpointState& state, const Workload& workload,
                      const store::BlockCodec& codec) {
  const Checker checker{path, state, workload, codec};
  checker.check_stage();
  const auto done = checker.check_done();
  checker.check_kept(done);
  checker.check_appends(done);
  checker.check_summary();
}

void rebuild_result_file(store::ResultFile& file, const std::string& journal, const std::string& job_text,
                         const store::BlockCodec& codec, std::uint64_t length, const store::Progress& progress) {
  constexpr std::size_t batch = 4096;
  std::vector<store::Block> blocks;
  store::replay_block_journal(journal, job_text, codec, length, [&](store::Block block) {
    blocks.push_back(std::move(block));
    if (blocks.size() >= batch) file.write(std::exchange(blocks, {}), progress);
  });
  file.write(std::move(blocks), progress);
}

}  // namespace pbrfit::runtime
