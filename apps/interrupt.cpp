#include "interrupt.hpp"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <memory>
#include <string>

namespace phongrast::cli {
namespace {

volatile std::sig_atomic_t interrupt_flag = 0;

extern "C" void on_interrupt(int) { interrupt_flag = 1; }

// Waiting this long before drawing keeps short renders free of flicker.
constexpr std::chrono::milliseconds kQuietStart{500};
constexpr int kBarWidth = 30;

}  // namespace

void catch_interrupts() {
    struct sigaction action {};
    action.sa_handler = on_interrupt;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
}

bool interrupted() { return interrupt_flag != 0; }

void stop_if_interrupted() {
    if (interrupted()) throw RenderCancelled();
}

ProgressCallback progress_bar(bool show_bar, std::string what) {
    const auto start = std::chrono::steady_clock::now();
    auto last_percent = std::make_shared<int>(-1);
    return [show_bar, what = std::move(what), start, last_percent](double fraction) {
        if (interrupted()) return false;
        if (!show_bar || std::chrono::steady_clock::now() - start < kQuietStart) return true;
        const int percent = static_cast<int>(fraction * 100.0);
        if (percent == *last_percent) return true;
        *last_percent = percent;
        const int filled = std::min(kBarWidth, std::max(0, static_cast<int>(fraction * kBarWidth)));
        const std::string bar = std::string(static_cast<std::size_t>(filled), '#') +
                                std::string(static_cast<std::size_t>(kBarWidth - filled), ' ');
        std::fprintf(stderr, "\r\033[K%s [%s] %3d%%", what.c_str(), bar.c_str(), percent);
        std::fflush(stderr);
        return true;
    };
}

void clear_progress_bar(bool show_bar) {
    if (!show_bar) return;
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
}

}  // namespace phongrast::cli
