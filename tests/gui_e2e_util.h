#pragma once
// Helpers for the end-to-end GUI tests (test_gui_e2e.cpp): child processes with timeouts (fork/exec,
// no shell), an Xvfb server, xdotool, the app's widget map, a graceful window close and image diffs.
// Everything that waits has a deadline; failures throw std::runtime_error with a message, which
// GoogleTest reports as the test's failure.
#include "renderer/image.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <dlfcn.h>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <poll.h>
#include <signal.h>
#include <sstream>
#include <stdexcept>
#include <string>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

extern char** environ;

namespace e2e {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using Seconds = std::chrono::duration<double>;

/// Deadlines are generous (they only matter when something is wrong); SHADOWSCOPE_E2E_TIME_SCALE
/// stretches them further for very slow builds.
inline Seconds scaled(double seconds) {
    double scale = 1.0;
    if (const char* s = std::getenv("SHADOWSCOPE_E2E_TIME_SCALE"); s && *s) scale = std::max(1.0, std::atof(s));
    return Seconds(seconds * scale);
}

inline std::string readText(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
}

inline void writeText(const fs::path& p, const std::string& text) {
    std::ofstream f(p, std::ios::binary | std::ios::trunc);
    f << text;
    if (!f) throw std::runtime_error("cannot write " + p.string());
}

inline std::string lastLines(const std::string& text, int lines) {
    size_t pos = text.size();
    if (pos > 0 && text[pos - 1] == '\n') --pos;
    for (int i = 0; i < lines; ++i) {
        const size_t nl = pos > 0 ? text.rfind('\n', pos - 1) : std::string::npos;
        if (nl == std::string::npos) return text;
        pos = nl;
    }
    return text.substr(pos + 1);
}

/// The executable `name` on PATH, or empty.
inline std::string findOnPath(const std::string& name) {
    const char* path = std::getenv("PATH");
    std::stringstream dirs(path ? path : "/usr/local/bin:/usr/bin:/bin");
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        if (dir.empty()) continue;
        const fs::path candidate = fs::path(dir) / name;
        if (::access(candidate.c_str(), X_OK) == 0) return candidate.string();
    }
    return {};
}

/// The current environment with some variables replaced (value) or removed (nullopt).
inline std::vector<std::string> environmentWith(const std::map<std::string, std::optional<std::string>>& changes) {
    std::vector<std::string> out;
    for (char** e = environ; e && *e; ++e) {
        const std::string entry(*e);
        const std::string key = entry.substr(0, entry.find('='));
        if (!changes.count(key)) out.push_back(entry);
    }
    for (const auto& [key, value] : changes)
        if (value) out.push_back(key + "=" + *value);
    return out;
}

/// A child process started with fork/exec (no shell). It gets SIGTERM when the test process dies,
/// so a killed test leaves no X server or app behind.
class Process {
public:
    Process() = default;
    Process(const Process&) = delete;
    Process& operator=(const Process&) = delete;
    ~Process() { stop(); }

    /// stdin is /dev/null; stdout and stderr go to the given descriptors (-1: /dev/null);
    /// `fd3`, when given, becomes the child's descriptor 3.
    void start(const std::string& exe, const std::vector<std::string>& args, const std::vector<std::string>& env,
               int outFd, int errFd, int fd3 = -1) {
        std::vector<std::string> argvStore{exe};
        argvStore.insert(argvStore.end(), args.begin(), args.end());
        std::vector<char*> argv, envp;
        for (auto& a : argvStore) argv.push_back(a.data());
        argv.push_back(nullptr);
        std::vector<std::string> envStore = env;
        for (auto& e : envStore) envp.push_back(e.data());
        envp.push_back(nullptr);
        const pid_t parent = ::getpid();
        const pid_t pid = ::fork();
        if (pid < 0) throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
        if (pid == 0) {
            // Only async-signal-safe calls from here on.
            ::prctl(PR_SET_PDEATHSIG, SIGTERM);
            if (::getppid() != parent) ::_exit(126);
            const int devnull = ::open("/dev/null", O_RDWR);
            ::dup2(devnull, 0);
            ::dup2(outFd >= 0 ? outFd : devnull, 1);
            ::dup2(errFd >= 0 ? errFd : devnull, 2);
            if (fd3 >= 0) {
                if (fd3 == 3) ::fcntl(3, F_SETFD, 0);
                else ::dup2(fd3, 3);
            }
            ::execve(exe.c_str(), argv.data(), envp.data());
            ::_exit(127);
        }
        pid_ = pid;
        exited_ = false;
        status_ = 0;
    }

    [[nodiscard]] pid_t pid() const noexcept { return pid_; }
    [[nodiscard]] bool started() const noexcept { return pid_ > 0; }

    /// True while the process runs (reaps it once it has exited).
    bool alive() {
        if (pid_ <= 0 || exited_) return false;
        int status = 0;
        const pid_t r = ::waitpid(pid_, &status, WNOHANG);
        if (r == pid_) {
            exited_ = true;
            status_ = status;
            return false;
        }
        return r == 0;
    }

    /// Waits up to `timeout` for the process to exit; true if it did.
    bool waitExit(Seconds timeout) {
        const auto deadline = Clock::now() + timeout;
        while (alive()) {
            if (Clock::now() > deadline) return false;
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        return true;
    }

    /// The exit code, or 128 + signal, or -1 while it runs.
    [[nodiscard]] int exitCode() const noexcept {
        if (!exited_) return -1;
        if (WIFEXITED(status_)) return WEXITSTATUS(status_);
        if (WIFSIGNALED(status_)) return 128 + WTERMSIG(status_);
        return -1;
    }

    void signal(int sig) {
        if (alive()) ::kill(pid_, sig);
    }

    /// SIGTERM, then SIGKILL after a grace period.
    void stop(Seconds grace = Seconds(5)) {
        if (!alive()) return;
        ::kill(pid_, SIGTERM);
        if (waitExit(grace)) return;
        ::kill(pid_, SIGKILL);
        waitExit(Seconds(10));
    }

private:
    pid_t pid_ = -1;
    bool exited_ = false;
    int status_ = 0;
};

struct RunResult {
    int exitCode = -1;
    bool timedOut = false;
    std::string output; // stdout and stderr
};

/// Runs a program to completion (killed after `timeout`), capturing stdout and stderr.
inline RunResult runProgram(const std::string& exe, const std::vector<std::string>& args,
                            const std::vector<std::string>& env, Seconds timeout) {
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
    RunResult r;
    Process p;
    try {
        p.start(exe, args, env, fds[1], fds[1]);
    } catch (...) {
        ::close(fds[0]);
        ::close(fds[1]);
        throw;
    }
    ::close(fds[1]);
    const auto deadline = Clock::now() + timeout;
    char buf[4096];
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
        if (left <= 0) {
            r.timedOut = true;
            p.signal(SIGKILL);
            break;
        }
        pollfd pfd{fds[0], POLLIN, 0};
        const int n = ::poll(&pfd, 1, int(std::min<long long>(left, 1000)));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) continue;
        const ssize_t got = ::read(fds[0], buf, sizeof buf);
        if (got <= 0) break;
        r.output.append(buf, size_t(got));
    }
    ::close(fds[0]);
    if (!p.waitExit(Seconds(10))) p.stop();
    r.exitCode = p.exitCode();
    return r;
}

/// Polls `done` until it returns true or the deadline passes; then throws naming `what`, with
/// `context()` appended.
inline void waitUntil(const std::string& what, Seconds timeout, const std::function<bool()>& done,
                      const std::function<std::string()>& context = {}) {
    const auto start = Clock::now();
    const auto deadline = start + timeout;
    for (;;) {
        if (done()) return;
        if (Clock::now() > deadline)
            throw std::runtime_error("timed out after " + std::to_string(int(timeout.count())) + " s waiting for " +
                                     what + (context ? "\n" + context() : std::string()));
        std::this_thread::sleep_for(std::chrono::milliseconds(15));
    }
}

/// An Xvfb server on a display it picks itself (-displayfd), so parallel tests don't collide.
class Xvfb {
public:
    void start(const std::string& exe, const fs::path& logFile, int width, int height) {
        int fds[2];
        if (::pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
        const int log = ::open(logFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
        const std::string screen = std::to_string(width) + "x" + std::to_string(height) + "x24";
        process_.start(exe, {"-displayfd", "3", "-screen", "0", screen, "-nolisten", "tcp", "-noreset"},
                       environmentWith({}), log, log, fds[1]);
        ::close(fds[1]);
        if (log >= 0) ::close(log);
        std::string text;
        const auto deadline = Clock::now() + scaled(30);
        while (text.find('\n') == std::string::npos) {
            const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
            if (left <= 0 || !process_.alive()) break;
            pollfd pfd{fds[0], POLLIN, 0};
            if (::poll(&pfd, 1, int(std::min<long long>(left, 200))) <= 0) continue;
            char buf[64];
            const ssize_t got = ::read(fds[0], buf, sizeof buf);
            if (got <= 0) break;
            text.append(buf, size_t(got));
        }
        ::close(fds[0]);
        if (text.find('\n') == std::string::npos || text.empty()) {
            process_.stop();
            throw std::runtime_error("Xvfb did not report its display number; its log:\n" + readText(logFile));
        }
        display_ = ":" + text.substr(0, text.find('\n'));
    }
    [[nodiscard]] const std::string& display() const noexcept { return display_; }
    bool alive() { return process_.alive(); }
    void stop() { process_.stop(); }

private:
    Process process_;
    std::string display_;
};

/// Asks the window to close the way a window manager's close button does: a WM_PROTOCOLS /
/// WM_DELETE_WINDOW client message (GLFW turns it into glfwWindowShouldClose). xdotool has no
/// command for it (windowkill drops the client's connection, windowclose destroys the window), so
/// this talks to the X server through libX11, loaded at run time (no build dependency on its headers).
inline void requestWindowClose(const std::string& display, unsigned long window) {
    void* lib = ::dlopen("libX11.so.6", RTLD_NOW | RTLD_LOCAL);
    if (!lib) throw std::runtime_error(std::string("cannot load libX11.so.6: ") + ::dlerror());
    struct Closer {
        void* l;
        ~Closer() { ::dlclose(l); }
    } closer{lib};
    using OpenDisplay = void* (*)(const char*);
    using CloseDisplay = int (*)(void*);
    using InternAtom = unsigned long (*)(void*, const char*, int);
    using SendEvent = int (*)(void*, unsigned long, int, long, void*);
    using Sync = int (*)(void*, int);
    const auto open = reinterpret_cast<OpenDisplay>(::dlsym(lib, "XOpenDisplay"));
    const auto close = reinterpret_cast<CloseDisplay>(::dlsym(lib, "XCloseDisplay"));
    const auto intern = reinterpret_cast<InternAtom>(::dlsym(lib, "XInternAtom"));
    const auto send = reinterpret_cast<SendEvent>(::dlsym(lib, "XSendEvent"));
    const auto sync = reinterpret_cast<Sync>(::dlsym(lib, "XSync"));
    if (!open || !close || !intern || !send || !sync) throw std::runtime_error("libX11.so.6 lacks a needed function");
    void* dpy = open(display.c_str());
    if (!dpy) throw std::runtime_error("cannot open display " + display);
    // Xlib's XClientMessageEvent (a stable ABI) inside the 24-long XEvent union.
    struct ClientMessage {
        int type;
        unsigned long serial;
        int sendEvent;
        void* display;
        unsigned long window;
        unsigned long messageType;
        int format;
        union {
            char b[20];
            short s[10];
            long l[5];
        } data;
    };
    union Event {
        int type;
        ClientMessage client;
        long pad[24];
    } event;
    std::memset(&event, 0, sizeof event);
    constexpr int kClientMessage = 33;
    event.client.type = kClientMessage;
    event.client.window = window;
    event.client.messageType = intern(dpy, "WM_PROTOCOLS", 0);
    event.client.format = 32;
    event.client.data.l[0] = long(intern(dpy, "WM_DELETE_WINDOW", 0));
    event.client.data.l[1] = 0; // CurrentTime
    const int ok = send(dpy, window, 0, 0 /* NoEventMask */, &event);
    sync(dpy, 0);
    close(dpy);
    if (!ok) throw std::runtime_error("XSendEvent failed");
}

struct Rect {
    double x = 0, y = 0, w = 0, h = 0;
    [[nodiscard]] double cx() const noexcept { return x + w * 0.5; }
    [[nodiscard]] double cy() const noexcept { return y + h * 0.5; }
};

/// One snapshot of SHADOWSCOPE_WIDGET_MAP.
struct WidgetMap {
    long frame = -1;
    int width = 0, height = 0;
    std::string status;
    std::map<std::string, Rect> widgets;
    std::map<std::string, double> counters; // e.g. passes.shadow, passes.eye_full, coarse

    [[nodiscard]] bool has(const std::string& id) const { return widgets.count(id) != 0; }
    [[nodiscard]] double counter(const std::string& name) const {
        const auto it = counters.find(name);
        return it == counters.end() ? -1.0 : it->second;
    }
    [[nodiscard]] std::string describe() const {
        std::ostringstream s;
        s << "widget map: frame " << frame << ", window " << width << "x" << height << ", status \"" << status << "\", "
          << widgets.size() << " widgets:";
        for (const auto& [id, r] : widgets) s << ' ' << id;
        return s.str();
    }
};

inline std::optional<WidgetMap> readWidgetMap(const fs::path& file) {
    std::error_code ec;
    if (!fs::exists(file, ec)) return std::nullopt;
    const nlohmann::json j = nlohmann::json::parse(readText(file), nullptr, false);
    if (j.is_discarded() || !j.is_object()) return std::nullopt;
    WidgetMap m;
    try {
        m.frame = j.at("frame").get<long>();
        m.width = int(std::lround(j.at("window").at(0).get<double>()));
        m.height = int(std::lround(j.at("window").at(1).get<double>()));
        m.status = j.value("status", "");
        for (const auto& [id, r] : j.at("widgets").items())
            m.widgets[id] =
                Rect{r.at(0).get<double>(), r.at(1).get<double>(), r.at(2).get<double>(), r.at(3).get<double>()};
        if (j.contains("counters"))
            for (const auto& [name, v] : j.at("counters").items()) m.counters[name] = v.get<double>();
    } catch (const std::exception&) {
        return std::nullopt;
    }
    return m;
}

/// A setting out of a config/preset JSON in preset layout ({"warp": {"method": ...}}), by its key.
inline const nlohmann::json* settingIn(const nlohmann::json& settings, const std::string& key) {
    const nlohmann::json* node = &settings;
    std::stringstream parts(key);
    std::string part;
    while (std::getline(parts, part, '.')) {
        if (!node->is_object() || !node->contains(part)) return nullptr;
        node = &(*node)[part];
    }
    return node;
}

struct ImageDiff {
    long differing = 0; // pixels with any channel different
    long total = 0;
    double meanAbs = 0; // mean absolute difference per RGB channel, 0..255
    int maxAbs = 0;
    [[nodiscard]] double fraction() const noexcept { return total ? double(differing) / double(total) : 0.0; }
    [[nodiscard]] std::string describe() const {
        std::ostringstream s;
        s << differing << " of " << total << " pixels differ (" << 100.0 * fraction() << "%), mean |diff| " << meanAbs
          << ", max |diff| " << maxAbs;
        return s.str();
    }
};

/// Compares the RGB of two images over `region` (x, y, w, h in pixels; whole image when absent).
inline ImageDiff diffImages(const geometry::analysis::Image& a, const geometry::analysis::Image& b,
                            std::optional<std::array<int, 4>> region = std::nullopt) {
    std::array<int, 4> r = region.value_or(std::array<int, 4>{0, 0, a.width, a.height});
    if (!region && (a.width != b.width || a.height != b.height))
        throw std::runtime_error("images differ in size: " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                                 " vs " + std::to_string(b.width) + "x" + std::to_string(b.height));
    if (r[0] < 0 || r[1] < 0 || r[2] <= 0 || r[3] <= 0 || r[0] + r[2] > std::min(a.width, b.width) ||
        r[1] + r[3] > std::min(a.height, b.height))
        throw std::runtime_error("compare region outside the images");
    ImageDiff d;
    double sum = 0;
    for (int y = r[1]; y < r[1] + r[3]; ++y)
        for (int x = r[0]; x < r[0] + r[2]; ++x) {
            const uint8_t* p = a.at(x, y);
            const uint8_t* q = b.at(x, y);
            bool differs = false;
            for (int c = 0; c < 3; ++c) {
                const int diff = std::abs(int(p[c]) - int(q[c]));
                sum += diff;
                d.maxAbs = std::max(d.maxAbs, diff);
                differs |= diff != 0;
            }
            d.differing += differs;
            ++d.total;
        }
    d.meanAbs = d.total ? sum / (3.0 * double(d.total)) : 0.0;
    return d;
}

} // namespace e2e
