#pragma once
// The window's input events, queued as GLFW reports them and handed to ImGui a frame at a time
// (issue 32, docs/design.md §2.6). ImGui 1.86 holds one pointer position, one level per mouse
// button and per key, a wheel sum and a character queue per frame: a press and release that both
// arrive between two frames would cancel out and be lost. takeFrame() takes the longest run from
// the front of the queue that one frame shows without losing anything or changing its order; the
// viewer applies it, draws a frame, and does not sleep while events wait.
//
// Pure (no GLFW, no ImGui): the codes are GLFW's, checked against its header in viewer.cpp.
#include <cstddef>
#include <deque>
#include <string>
#include <variant>
#include <vector>

namespace ui::input {

/// GLFW's actions and the range of its modifier keys (GLFW_KEY_LEFT_SHIFT … GLFW_KEY_RIGHT_SUPER).
inline constexpr int kRelease = 0, kPress = 1, kRepeat = 2;
inline constexpr int kFirstModifierKey = 340, kLastModifierKey = 347;

struct KeyEvent {
    int key = -1, scancode = 0, action = kPress, mods = 0;
};
struct CharEvent {
    unsigned codepoint = 0;
};
struct MouseButtonEvent {
    int button = 0, action = kPress, mods = 0;
};
struct ScrollEvent {
    double dx = 0, dy = 0;
};
struct CursorPosEvent {
    double x = 0, y = 0;
};
struct FocusEvent {
    bool focused = true;
};
struct CursorEnterEvent {
    bool entered = true;
};
struct DropEvent {
    std::vector<std::string> paths;
};

using InputEvent = std::variant<KeyEvent, CharEvent, MouseButtonEvent, ScrollEvent, CursorPosEvent, FocusEvent,
                                CursorEnterEvent, DropEvent>;

[[nodiscard]] constexpr bool isModifierKey(int key) noexcept {
    return key >= kFirstModifierKey && key <= kLastModifierKey;
}

/// How many events from the front of `events` one ImGui frame can take: at least one (unless the
/// queue is empty), and it stops before an event the frame could not show after the ones taken:
///  - a second transition of the same mouse button or key (the level would hide the first);
///  - a button or wheel event after a pointer move, and a move after them (the move is seen on
///    its own first, as ImGui's hover of the previous frame decides what a click or wheel hits);
///  - a modifier change after a key, character, button or wheel event (which reads the modifiers);
///  - a key ImGui acts on (a press that types no character: Return, Tab, Ctrl+A…) after typed
///    characters or another key press, and anything typed after it (ImGui's text field takes a
///    frame's characters before its keys, and one editing key per frame);
///  - keys or characters after a button or wheel event, and those after keys or characters;
///  - anything after a focus change or a file drop, which take a frame of their own.
/// Cursor moves within a frame coalesce (the last one counts); wheel steps add up.
[[nodiscard]] std::size_t framePrefix(const std::deque<InputEvent>& events);

class InputQueue {
public:
    /// Appends an event; a cursor move right after another replaces it (they share a frame anyway),
    /// so a flood of motion while the window cannot draw stays one event.
    void push(InputEvent event);
    /// Removes and returns the events of the next frame (framePrefix); empty when the queue is.
    std::vector<InputEvent> takeFrame();
    [[nodiscard]] bool empty() const noexcept { return events_.empty(); }
    [[nodiscard]] std::size_t size() const noexcept { return events_.size(); }

private:
    std::deque<InputEvent> events_;
};

} // namespace ui::input
