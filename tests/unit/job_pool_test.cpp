// SPDX-License-Identifier: MIT
// The job pool's reading of a run folder (study/job_pool.hpp): the same states, on the same
// folders, as the Slurm path's scripts/slurm_array.py run_state, so a study, a calibration and a
// job array agree on what is finished, what resumes and what starts again.
#include "drydem/study/job_pool.hpp"
#include <gtest/gtest.h>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace {
using namespace drydem;
namespace fs = std::filesystem;

struct Folder {
    std::string name;
    std::string summary; ///< summary.json text; empty = none
    bool checkpoint = false, config = false;
    RunFolder expected;
};

fs::path make(const fs::path& root, const Folder& f) {
    const fs::path d = root / f.name;
    fs::create_directories(d);
    if (!f.summary.empty()) std::ofstream(d / "summary.json") << f.summary;
    if (f.checkpoint) {
        fs::create_directories(d / "checkpoint");
        std::ofstream(d / "checkpoint" / "state.bin") << "x";
    }
    if (f.config) std::ofstream(d / "config.toml") << "[run]\n";
    return d;
}

const Folder kFolders[] = {
    {"new", "", false, false, RunFolder::fresh},
    {"partial", "", false, true, RunFolder::partial},
    {"killed", "", true, true, RunFolder::stopped},
    {"completed", R"({"status": "completed", "stop_reason": "completed"})", true, true,
     RunFolder::completed},
    {"interrupted", R"({"status": "failed", "stop_reason": "interrupted"})", true, true,
     RunFolder::stopped},
    {"stop_after", R"({"status": "failed", "stop_reason": "stop_after_steps"})", true, true,
     RunFolder::stopped},
    {"interrupted_no_checkpoint", R"({"status": "failed", "stop_reason": "interrupted"})", false,
     true, RunFolder::failed},
    {"blow_up", R"({"status": "failed", "stop_reason": "blow_up"})", true, true, RunFolder::failed},
    {"unreadable_summary", "{not json", false, true, RunFolder::partial},
};

TEST(JobPool, RunFolderStates) {
    const fs::path root = fs::temp_directory_path() / "drydem_job_pool_test";
    fs::remove_all(root);
    for (const Folder& f : kFolders)
        EXPECT_EQ(run_folder_state(make(root, f)), f.expected) << f.name;
    EXPECT_TRUE(resumable_stop_reason("interrupted"));
    EXPECT_FALSE(resumable_stop_reason("max_process_time"));
    fs::remove_all(root);
}

// The Slurm path reads the same folders the same way (where Debian's python3 is installed).
TEST(JobPool, TheSlurmPathReadsTheSameStates) {
    if (!fs::exists("/usr/bin/python3")) GTEST_SKIP() << "no /usr/bin/python3";
    const fs::path root = fs::temp_directory_path() / "drydem_job_pool_py_test";
    fs::remove_all(root);
    std::string expected;
    for (const Folder& f : kFolders) {
        make(root, f);
        expected += f.name + " " + std::string(to_string(f.expected)) + "\n";
    }
    const fs::path out = root / "states.txt";
    const std::string cmd =
        "/usr/bin/python3 -c \"import sys, os; sys.path.insert(0, '" DRYDEM_SOURCE_DIR
        "/scripts'); import slurm_array; r = sys.argv[1]; print(''.join(n + ' ' + "
        "slurm_array.run_state(os.path.join(r, n)) + chr(10) for n in sys.argv[2:]), end='')\" " +
        root.string();
    std::string names;
    for (const Folder& f : kFolders) names += " " + f.name;
    ASSERT_EQ(std::system((cmd + names + " > " + out.string()).c_str()), 0);
    std::ifstream in(out);
    const std::string got((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(got, expected);
    fs::remove_all(root);
}

} // namespace
