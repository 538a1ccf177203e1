// SPDX-License-Identifier: MIT
// The console and log.txt of a drying run: the logger, and the progress line that updates in
// place on a terminal.
#include "drydem/drying/run_observer.hpp"
#include <spdlog/sinks/base_sink.h>
#include <spdlog/sinks/basic_file_sink.h>
#include <spdlog/sinks/null_sink.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>
#include <cstdio>
#include <mutex>

namespace drydem {

void StatusLine::show(const std::string& line) {
    std::fprintf(stderr, "\r\033[K%s", line.c_str());
    std::fflush(stderr);
    shown_ = true;
}

void StatusLine::clear() {
    if (shown_) std::fputs("\r\033[K", stderr);
    shown_ = false;
}

namespace {
/// The console sink behind a status line: a message first clears the line it would cut into.
class ConsoleSink final : public spdlog::sinks::base_sink<std::mutex> {
public:
    explicit ConsoleSink(StatusLine& status)
        : status_(status), inner_(std::make_shared<spdlog::sinks::stderr_color_sink_mt>()) {
        inner_->set_pattern("%v");
    }

protected:
    void sink_it_(const spdlog::details::log_msg& msg) override {
        status_.clear();
        inner_->log(msg);
    }
    void flush_() override { inner_->flush(); }

private:
    StatusLine& status_;
    std::shared_ptr<spdlog::sinks::stderr_color_sink_mt> inner_;
};
} // namespace

std::shared_ptr<spdlog::logger> make_run_logger(const std::filesystem::path& dir, bool quiet,
                                                bool append, StatusLine& status) {
    auto file =
        std::make_shared<spdlog::sinks::basic_file_sink_mt>((dir / "log.txt").string(), !append);
    auto console = std::make_shared<ConsoleSink>(status);
    console->set_level(quiet ? spdlog::level::warn : spdlog::level::info);
    file->set_pattern("[%Y-%m-%d %H:%M:%S.%e] [%l] %v");
    auto log = std::make_shared<spdlog::logger>("drydem", spdlog::sinks_init_list{console, file});
    log->set_level(spdlog::level::debug);
    log->flush_on(spdlog::level::info);
    return log;
}

std::shared_ptr<spdlog::logger> silent_logger() {
    return std::make_shared<spdlog::logger>("drydem",
                                            std::make_shared<spdlog::sinks::null_sink_mt>());
}

} // namespace drydem
