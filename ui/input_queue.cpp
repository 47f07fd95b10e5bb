#include "input_queue.h"

#include <algorithm>
#include <iterator>

namespace ui::input {

namespace {

/// What the frame being filled holds so far.
struct Frame {
    std::vector<int> keys, buttons; // keys and buttons with a transition in this frame
    bool moved = false;             // a cursor move or enter/leave
    bool pointerAction = false;     // a button transition or the wheel
    bool keyboard = false;          // a non-modifier key transition or a character
    bool typed = false;             // characters, or a key press that typed one
    bool command = false;           // a key press that typed nothing: ImGui acts on the key
    bool closed = false;            // a focus change or a drop: nothing more joins
    std::size_t count = 0;
};

bool contains(const std::vector<int>& v, int x) { return std::find(v.begin(), v.end(), x) != v.end(); }

/// Adds `e` to the frame, or returns false when it must start the next one. `next` is the event
/// after it, if any (a key press followed by its character typed it).
class Joiner {
public:
    Joiner(Frame& f, const InputEvent* next) : f_(f), next_(next) {}

    bool operator()(const KeyEvent& e) const {
        if (e.action == kRepeat || e.key < 0) return true; // no level changes (ImGui repeats itself)
        if (contains(f_.keys, e.key)) return false;
        if (isModifierKey(e.key)) {
            if (f_.keyboard || f_.pointerAction) return false;
        } else {
            if (f_.pointerAction) return false;
            if (e.action == kPress) {
                const bool typesChar = next_ && std::holds_alternative<CharEvent>(*next_);
                if (f_.command || (!typesChar && f_.typed)) return false;
                (typesChar ? f_.typed : f_.command) = true;
            }
            f_.keyboard = true;
        }
        f_.keys.push_back(e.key);
        return true;
    }
    bool operator()(const CharEvent&) const {
        if (f_.pointerAction || f_.command) return false;
        f_.keyboard = f_.typed = true;
        return true;
    }
    bool operator()(const MouseButtonEvent& e) const {
        if (contains(f_.buttons, e.button) || f_.moved || f_.keyboard) return false;
        f_.buttons.push_back(e.button);
        f_.pointerAction = true;
        return true;
    }
    bool operator()(const ScrollEvent&) const {
        if (f_.moved || f_.keyboard) return false;
        f_.pointerAction = true;
        return true;
    }
    bool operator()(const CursorPosEvent&) const { return pointerMove(); }
    bool operator()(const CursorEnterEvent&) const { return pointerMove(); }
    bool operator()(const FocusEvent&) const { return alone(); }
    bool operator()(const DropEvent&) const { return alone(); }

private:
    bool pointerMove() const {
        if (f_.pointerAction) return false;
        f_.moved = true;
        return true;
    }
    /// Focus: ImGui 1.86 clears its keys in the NewFrame after a focus loss, so a key of the same
    /// frame would be lost; a drop loads a scene, which the frame's other input should not race.
    bool alone() const {
        if (f_.count > 0) return false;
        f_.closed = true;
        return true;
    }

    Frame& f_;
    const InputEvent* next_;
};

} // namespace

std::size_t framePrefix(const std::deque<InputEvent>& events) {
    Frame frame;
    for (auto it = events.begin(); it != events.end(); ++it) {
        if (frame.closed) break;
        const InputEvent* next = std::next(it) != events.end() ? &*std::next(it) : nullptr;
        if (!std::visit(Joiner(frame, next), *it)) break;
        ++frame.count;
    }
    // (Every event joins an empty frame; the floor only guards that a frame always takes one.)
    return events.empty() ? 0 : std::max<std::size_t>(frame.count, 1);
}

void InputQueue::push(InputEvent event) {
    if (std::holds_alternative<CursorPosEvent>(event) && !events_.empty() &&
        std::holds_alternative<CursorPosEvent>(events_.back())) {
        events_.back() = std::move(event);
        return;
    }
    events_.push_back(std::move(event));
}

std::vector<InputEvent> InputQueue::takeFrame() {
    const std::size_t n = framePrefix(events_);
    std::vector<InputEvent> frame(std::make_move_iterator(events_.begin()),
                                  std::make_move_iterator(events_.begin() + std::ptrdiff_t(n)));
    events_.erase(events_.begin(), events_.begin() + std::ptrdiff_t(n));
    return frame;
}

} // namespace ui::input
