// A test helper: drops files onto an X11 window as a file manager does, through the XDND protocol
// (https://freedesktop.org/wiki/Specifications/XDND, version 5), since xdotool cannot drag files.
//
//   xdnd_drop WINDOW FILE... [--at X Y]
//
// WINDOW is the target's window id (decimal or 0x hex, as xdotool prints it); FILE paths are sent
// as a text/uri-list; X Y are the drop point in the window (default: its centre). It plays the
// source side: an unmapped window owns XdndSelection; XdndEnter and XdndPosition go to the target,
// which answers XdndStatus; XdndDrop, then the target asks for the selection (SelectionRequest),
// gets the list and ends with XdndFinished. GLFW 3.3 (x11_window.c) accepts versions up to 5 and
// text/uri-list only, reports the position as a cursor move and the list to its drop callback.
// Exit 0 when the target accepted and finished the drop, 1 otherwise (with the reason on stderr);
// every wait gives up after 20 s.
#include <X11/Xatom.h>
#include <X11/Xlib.h>

#include <poll.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

constexpr long kVersion = 5;
constexpr auto kTimeout = std::chrono::seconds(20);

[[noreturn]] void fail(const std::string& why) {
    std::fprintf(stderr, "xdnd_drop: %s\n", why.c_str());
    std::exit(1);
}

/// A file path as a file:// URI: unreserved characters and '/' as they are, the rest %-escaped.
std::string fileUri(const std::string& path) {
    std::string uri = "file://";
    for (const unsigned char c : path) {
        if (std::isalnum(c) || std::strchr("/-_.~", c)) uri += char(c);
        else {
            char esc[4];
            std::snprintf(esc, sizeof esc, "%%%02X", c);
            uri += esc;
        }
    }
    return uri;
}

struct Atoms {
    Atom aware, enter, position, status, drop, finished, selection, actionCopy, uriList;
    explicit Atoms(Display* d)
        : aware(XInternAtom(d, "XdndAware", False)), enter(XInternAtom(d, "XdndEnter", False)),
          position(XInternAtom(d, "XdndPosition", False)), status(XInternAtom(d, "XdndStatus", False)),
          drop(XInternAtom(d, "XdndDrop", False)), finished(XInternAtom(d, "XdndFinished", False)),
          selection(XInternAtom(d, "XdndSelection", False)), actionCopy(XInternAtom(d, "XdndActionCopy", False)),
          uriList(XInternAtom(d, "text/uri-list", False)) {}
};

class Drag {
public:
    Drag(Display* d, Window target, std::string uriList)
        : d_(d), atoms_(d), target_(target), list_(std::move(uriList)),
          source_(XCreateSimpleWindow(d, DefaultRootWindow(d), 0, 0, 1, 1, 0, 0, 0)) {}

    /// The XDND version both sides speak (the target's XdndAware property).
    long negotiateVersion() {
        Atom type = None;
        int format = 0;
        unsigned long count = 0, after = 0;
        unsigned char* data = nullptr;
        if (XGetWindowProperty(d_, target_, atoms_.aware, 0, 1, False, XA_ATOM, &type, &format, &count, &after,
                               &data) != Success ||
            type != XA_ATOM || count < 1 || !data)
            fail("the target window has no XdndAware property (it takes no drops)");
        const long theirs = long(*reinterpret_cast<Atom*>(data));
        XFree(data);
        version_ = std::min(theirs, kVersion);
        if (version_ < 2) fail("the target speaks XDND version " + std::to_string(theirs) + ", this needs 2 or later");
        return version_;
    }

    void run(int x, int y) {
        if (!XSetSelectionOwner(d_, atoms_.selection, source_, CurrentTime) ||
            XGetSelectionOwner(d_, atoms_.selection) != source_)
            fail("could not own XdndSelection");
        int rootX = 0, rootY = 0;
        Window child = None;
        XTranslateCoordinates(d_, target_, DefaultRootWindow(d_), x, y, &rootX, &rootY, &child);
        send(atoms_.enter, {long(source_), version_ << 24, long(atoms_.uriList), 0, 0});
        send(atoms_.position,
             {long(source_), 0, (long(rootX) << 16) | (long(rootY) & 0xffff), CurrentTime, long(atoms_.actionCopy)});
        const XClientMessageEvent status = waitFor(atoms_.status, "XdndStatus");
        if (!(status.data.l[1] & 1)) fail("the target refused the drop (XdndStatus without accept)");
        send(atoms_.drop, {long(source_), 0, CurrentTime, 0, 0});
        waitFor(atoms_.finished, "XdndFinished");
        if (!served_) fail("the target finished without asking for the data");
        if (version_ >= 5 && !(finished_.data.l[1] & 1)) fail("the target reported the drop as failed");
    }

private:
    void send(Atom type, std::initializer_list<long> data) {
        XEvent e;
        std::memset(&e, 0, sizeof e);
        e.xclient.type = ClientMessage;
        e.xclient.window = target_;
        e.xclient.message_type = type;
        e.xclient.format = 32;
        int i = 0;
        for (const long v : data) e.xclient.data.l[i++] = v;
        XSendEvent(d_, target_, False, NoEventMask, &e);
        XFlush(d_);
    }

    /// Answers the target's request for the selection: the uri list as text/uri-list.
    void serve(const XSelectionRequestEvent& r) {
        XEvent reply;
        std::memset(&reply, 0, sizeof reply);
        reply.xselection.type = SelectionNotify;
        reply.xselection.requestor = r.requestor;
        reply.xselection.selection = r.selection;
        reply.xselection.target = r.target;
        reply.xselection.time = r.time;
        reply.xselection.property = None;
        if (r.target == atoms_.uriList && r.property != None) {
            XChangeProperty(d_, r.requestor, r.property, atoms_.uriList, 8, PropModeReplace,
                            reinterpret_cast<const unsigned char*>(list_.data()), int(list_.size()));
            reply.xselection.property = r.property;
            served_ = true;
        }
        XSendEvent(d_, r.requestor, False, NoEventMask, &reply);
        XFlush(d_);
    }

    /// Handles events (serving selection requests) until a client message of `type` arrives.
    XClientMessageEvent waitFor(Atom type, const char* name) {
        const auto deadline = std::chrono::steady_clock::now() + kTimeout;
        for (;;) {
            while (XPending(d_)) {
                XEvent e;
                XNextEvent(d_, &e);
                if (e.type == SelectionRequest) serve(e.xselectionrequest);
                else if (e.type == ClientMessage && e.xclient.message_type == type) {
                    if (type == atoms_.finished) finished_ = e.xclient;
                    return e.xclient;
                }
            }
            const auto left =
                std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
            if (left.count() <= 0) fail(std::string("timed out waiting for ") + name + " from the target");
            pollfd p{ConnectionNumber(d_), POLLIN, 0};
            ::poll(&p, 1, int(std::min<long long>(left.count(), 200)));
        }
    }

    Display* d_;
    Atoms atoms_;
    Window target_;
    std::string list_;
    Window source_;
    long version_ = kVersion;
    bool served_ = false;
    XClientMessageEvent finished_{};
};

} // namespace

int main(int argc, char** argv) {
    std::vector<std::string> files;
    int x = -1, y = -1;
    for (int i = 2; i < argc; ++i) {
        if (std::string(argv[i]) == "--at" && i + 2 < argc) {
            x = std::atoi(argv[i + 1]);
            y = std::atoi(argv[i + 2]);
            i += 2;
        } else files.emplace_back(argv[i]);
    }
    if (argc < 3 || files.empty()) {
        std::fprintf(stderr, "usage: xdnd_drop WINDOW FILE... [--at X Y]\n");
        return 2;
    }
    const Window target = Window(std::strtoul(argv[1], nullptr, 0));
    Display* d = XOpenDisplay(nullptr);
    if (!d) fail("cannot open the display (DISPLAY is not set or the server is gone)");
    XWindowAttributes attributes;
    if (!XGetWindowAttributes(d, target, &attributes)) fail("no window " + std::string(argv[1]));
    if (x < 0 || y < 0) {
        x = attributes.width / 2;
        y = attributes.height / 2;
    }
    std::string list;
    for (const auto& f : files) list += fileUri(f) + "\r\n";
    Drag drag(d, target, list);
    drag.negotiateVersion();
    drag.run(x, y);
    XCloseDisplay(d);
    return 0;
}
