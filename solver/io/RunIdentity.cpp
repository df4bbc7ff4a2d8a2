// run.json and the check that a checkpoint belongs to the run of its folder.
#include "solver/io/RunIdentity.h"

#include "solver/core/Checksum.h"
#include "solver/core/InputError.h"
#include "solver/io/CaseWriter.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <random>

namespace lbdem::io {

namespace fs = std::filesystem;

namespace {

constexpr const char* kFileName = "run.json";

/// 32 hex digits from the system's random source: two runs of one case get different ids.
std::string randomRunId() {
    std::random_device source;
    std::string id;
    const char* const digits = "0123456789abcdef";
    for (int word = 0; word < 4; ++word) {
        std::uint32_t bits = source();
        for (int k = 0; k < 8; ++k, bits >>= 4)
            id += digits[bits & 0xf];
    }
    return id;
}

} // namespace

RunIdentity newRunIdentity(const std::string& caseToml) {
    return {randomRunId(), solver::checksumOf(caseToml)};
}

void writeRunIdentity(const fs::path& dir, const RunIdentity& identity) {
    const nlohmann::json json{{"run_id", identity.run_id}, {"case_hash", identity.case_hash}};
    writeFileAtomically((dir / kFileName).string(), json.dump(2) + "\n");
}

std::optional<RunIdentity> readRunIdentity(const fs::path& dir) {
    const fs::path path = dir / kFileName;
    std::error_code error;
    if (!fs::exists(path, error)) return std::nullopt;
    std::ifstream in(path);
    const auto json = nlohmann::json::parse(in, nullptr, false);
    if (json.is_discarded() || !json.is_object() || !json.contains("run_id") ||
        !json["run_id"].is_string() || !json.contains("case_hash") ||
        !json["case_hash"].is_string() || json["run_id"].get<std::string>().empty())
        throw solver::InputError(path.string() +
                                 " is damaged: expected a JSON object with the strings run_id "
                                 "and case_hash");
    return RunIdentity{json["run_id"].get<std::string>(), json["case_hash"].get<std::string>()};
}

void checkCheckpointBelongs(const std::string& path, const CheckpointData& checkpoint,
                            const std::optional<RunIdentity>& folder) {
    const std::string dir = fs::path(path).parent_path().string();
    const std::string remedy =
        "; was it copied in from another run's folder? Put back this run's own checkpoint, or "
        "start the run again with lbdem run " +
        (fs::path(dir) / "case.toml").string() + " --out " + dir + " --force";
    if (!folder) {
        if (checkpoint.run_id.empty()) return; // both older than run ids: nothing to compare
        throw solver::InputError(path + " belongs to run " + checkpoint.run_id +
                                 ", but its folder has no run.json to say which run it holds" +
                                 remedy);
    }
    if (checkpoint.run_id.empty())
        throw solver::InputError(path + " names no run, but its folder holds run " +
                                 folder->run_id + remedy);
    if (checkpoint.run_id != folder->run_id)
        throw solver::InputError(path + " belongs to run " + checkpoint.run_id + ", not to run " +
                                 folder->run_id + " of its folder (run.json)" + remedy);
    if (checkpoint.case_hash != folder->case_hash ||
        solver::checksumOf(checkpoint.case_toml) != folder->case_hash)
        throw solver::InputError(
            path + " holds another case (hash " + solver::checksumOf(checkpoint.case_toml) +
            ") than its folder's run (case hash " + folder->case_hash + " in run.json)" + remedy);
}

} // namespace lbdem::io
