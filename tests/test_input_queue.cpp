// The window's input queue (ui/input_queue.h, issue 32): the events GLFW reports are split into
// frames so that ImGui 1.86, which holds one level per button and key per frame, loses none of
// them. Frames are written as text, events in order, frames separated by " | ":
//   ctrl+ / a- .... key press / release (ctrl, shift, a, ret, tab, f12, else the key code)
//   a* ............ key repeat          'a' ........ typed character
//   b0+ / b0- ..... mouse button        w+1 ........ wheel step
//   m ............. cursor move         in / out ... cursor enter / leave
//   focus+/- ...... window focus        drop(n) .... n files dropped
#define GLFW_INCLUDE_NONE
#include "ui/input_queue.h"

#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace ui::input;

namespace {

// The queue's codes are GLFW's (viewer.cpp checks the same against the header it uses).
static_assert(kPress == GLFW_PRESS && kRelease == GLFW_RELEASE && kRepeat == GLFW_REPEAT);
static_assert(kFirstModifierKey == GLFW_KEY_LEFT_SHIFT && kLastModifierKey == GLFW_KEY_RIGHT_SUPER);

KeyEvent down(int key) { return {key, 0, kPress, 0}; }
KeyEvent up(int key) { return {key, 0, kRelease, 0}; }
KeyEvent repeat(int key) { return {key, 0, kRepeat, 0}; }
CharEvent ch(char c) { return {unsigned(c)}; }
MouseButtonEvent press(int b = 0) { return {b, kPress, 0}; }
MouseButtonEvent release(int b = 0) { return {b, kRelease, 0}; }
ScrollEvent wheel(double dy = 1) { return {0, dy}; }
CursorPosEvent move(double x = 1, double y = 1) { return {x, y}; }

/// A key typed as a user does: press, its character, release.
std::vector<InputEvent> typed(int key, char c) { return {down(key), ch(c), up(key)}; }

std::string keyName(int key) {
    static const std::map<int, std::string> names{
        {GLFW_KEY_LEFT_CONTROL, "ctrl"}, {GLFW_KEY_LEFT_SHIFT, "shift"}, {GLFW_KEY_ENTER, "ret"},
        {GLFW_KEY_TAB, "tab"},           {GLFW_KEY_F12, "f12"},
    };
    if (const auto it = names.find(key); it != names.end()) return it->second;
    if (key >= GLFW_KEY_A && key <= GLFW_KEY_Z) return std::string(1, char('a' + key - GLFW_KEY_A));
    if (key >= GLFW_KEY_0 && key <= GLFW_KEY_9) return std::string(1, char('0' + key - GLFW_KEY_0));
    return std::to_string(key);
}

struct Describe {
    std::string operator()(const KeyEvent& e) const {
        return keyName(e.key) + (e.action == kPress ? "+" : e.action == kRelease ? "-" : "*");
    }
    std::string operator()(const CharEvent& e) const { return "'" + std::string(1, char(e.codepoint)) + "'"; }
    std::string operator()(const MouseButtonEvent& e) const {
        return "b" + std::to_string(e.button) + (e.action == kPress ? "+" : "-");
    }
    std::string operator()(const ScrollEvent& e) const { return "w" + std::string(e.dy >= 0 ? "+" : "-") + "1"; }
    std::string operator()(const CursorPosEvent&) const { return "m"; }
    std::string operator()(const CursorEnterEvent& e) const { return e.entered ? "in" : "out"; }
    std::string operator()(const FocusEvent& e) const { return e.focused ? "focus+" : "focus-"; }
    std::string operator()(const DropEvent& e) const { return "drop(" + std::to_string(e.paths.size()) + ")"; }
};

/// The frames the queue makes of `events`, pushed all at once (the window drew nothing meanwhile).
std::vector<std::vector<InputEvent>> framesOf(const std::vector<InputEvent>& events) {
    InputQueue q;
    for (const auto& e : events) q.push(e);
    std::vector<std::vector<InputEvent>> frames;
    while (!q.empty()) {
        frames.push_back(q.takeFrame());
        if (frames.back().empty()) break; // would loop forever: the test fails below
    }
    return frames;
}

std::string describe(const std::vector<std::vector<InputEvent>>& frames) {
    std::ostringstream s;
    for (size_t f = 0; f < frames.size(); ++f) {
        if (f) s << " | ";
        for (size_t i = 0; i < frames[f].size(); ++i) s << (i ? " " : "") << std::visit(Describe{}, frames[f][i]);
    }
    return s.str();
}

std::string split(const std::vector<InputEvent>& events) { return describe(framesOf(events)); }

std::vector<InputEvent> concat(std::initializer_list<std::vector<InputEvent>> parts) {
    std::vector<InputEvent> all;
    for (const auto& p : parts) all.insert(all.end(), p.begin(), p.end());
    return all;
}

/// What ImGui 1.86 holds at the end of a frame: key and button levels, the modifiers, the typed
/// characters and the wheel, replayed from the frames.
struct ImGuiLevels {
    std::set<int> keys, buttons;
    [[nodiscard]] bool ctrl() const { return keys.count(GLFW_KEY_LEFT_CONTROL) || keys.count(GLFW_KEY_RIGHT_CONTROL); }
};

} // namespace

TEST(InputQueue, EmptyQueueGivesNoFrame) {
    InputQueue q;
    EXPECT_TRUE(q.takeFrame().empty());
    EXPECT_EQ(framePrefix({}), 0u);
}

TEST(InputQueue, PressAndReleaseOfOneButtonTakeTwoFrames) {
    EXPECT_EQ(split({press(), release()}), "b0+ | b0-");
    // Different buttons are different levels: they share a frame.
    EXPECT_EQ(split({press(0), press(1), release(0), release(1)}), "b0+ b1+ | b0- b1-");
}

TEST(InputQueue, ThePointerMovesAFrameBeforeItClicksOrTurnsTheWheel) {
    // A fast click elsewhere: the move is seen on its own (ImGui's hover of the previous frame
    // decides what a click hits), then the press, then the release.
    EXPECT_EQ(split({move(), press(), release()}), "m | b0+ | b0-");
    // A drag: the moves after the press are a frame of their own, and the release comes after them.
    EXPECT_EQ(split({press(), move(), move(2, 2), release()}), "b0+ | m | b0-");
    EXPECT_EQ(split({move(), wheel(), move(), wheel()}), "m | w+1 | m | w+1");
    EXPECT_EQ(split({CursorEnterEvent{true}, move(), press()}), "in m | b0+");
}

TEST(InputQueue, TypedCharactersComeAFrameBeforeReturn) {
    // "ab" then a 10 ms Return: Return is pressed in a frame with no characters (ImGui's field
    // takes a frame's characters first and then one editing key), and released in the next.
    const auto events =
        concat({typed(GLFW_KEY_A, 'a'), typed(GLFW_KEY_B, 'b'), {down(GLFW_KEY_ENTER), up(GLFW_KEY_ENTER)}});
    EXPECT_EQ(split(events), "a+ 'a' | a- b+ 'b' | b- ret+ | ret-");
    // Characters without their keys (an input method): Return still waits for the next frame.
    EXPECT_EQ(split({ch('1'), ch('2'), down(GLFW_KEY_ENTER), up(GLFW_KEY_ENTER)}), "'1' '2' | ret+ | ret-");
    // And what is typed after Return comes after it.
    EXPECT_EQ(split(concat({{down(GLFW_KEY_ENTER), up(GLFW_KEY_ENTER)}, typed(GLFW_KEY_X, 'x')})),
              "ret+ | ret- x+ 'x' | x-");
    // A character after an editing key waits for the next frame even without its key press.
    EXPECT_EQ(split({down(GLFW_KEY_TAB), up(GLFW_KEY_B), ch('x')}), "tab+ b- | 'x'");
    // Two editing keys in one frame: ImGui 1.86 acts on one of them.
    EXPECT_EQ(split({down(GLFW_KEY_TAB), down(GLFW_KEY_ENTER)}), "tab+ | ret+");
}

TEST(InputQueue, RepeatedTypingKeepsEveryCharacterInOrder) {
    // "999": the same key three times, each press and each release in a frame of its own (one
    // frame holding a release and the next press would show the key held throughout).
    const auto events = concat({typed(GLFW_KEY_9, '9'), typed(GLFW_KEY_9, '9'), typed(GLFW_KEY_9, '9')});
    EXPECT_EQ(split(events), "9+ '9' | 9- | 9+ '9' | 9- | 9+ '9' | 9-");
    // A held key: GLFW's repeats change no level, the characters stay in the frame.
    EXPECT_EQ(
        split({down(GLFW_KEY_A), ch('a'), repeat(GLFW_KEY_A), ch('a'), repeat(GLFW_KEY_A), ch('a'), up(GLFW_KEY_A)}),
        "a+ 'a' a* 'a' a* 'a' | a-");
}

TEST(InputQueue, CtrlAKeepsCtrlDownWhileAIsDown) {
    const std::vector<InputEvent> events{down(GLFW_KEY_LEFT_CONTROL), down(GLFW_KEY_A), up(GLFW_KEY_A),
                                         up(GLFW_KEY_LEFT_CONTROL)};
    const auto frames = framesOf(events);
    EXPECT_EQ(describe(frames), "ctrl+ a+ | a- | ctrl-");
    // Replayed as ImGui holds it: a frame in which A went down with Ctrl held.
    ImGuiLevels levels;
    bool chord = false;
    for (const auto& frame : frames) {
        bool aPressed = false;
        for (const auto& e : frame)
            if (const auto* k = std::get_if<KeyEvent>(&e)) {
                if (k->action == kPress) levels.keys.insert(k->key);
                if (k->action == kRelease) levels.keys.erase(k->key);
                aPressed |= k->key == GLFW_KEY_A && k->action == kPress;
            }
        chord |= aPressed && levels.ctrl() && levels.keys.count(GLFW_KEY_A);
    }
    EXPECT_TRUE(chord) << describe(frames);
    // Typing "a" and then pressing Ctrl (to ctrl+click) is no Ctrl+A: Ctrl waits for the next frame.
    EXPECT_EQ(split({down(GLFW_KEY_A), ch('a'), down(GLFW_KEY_LEFT_CONTROL)}), "a+ 'a' | ctrl+");
    // Shift+a types 'A' with Shift down throughout.
    EXPECT_EQ(split({down(GLFW_KEY_LEFT_SHIFT), down(GLFW_KEY_A), ch('A'), up(GLFW_KEY_A), up(GLFW_KEY_LEFT_SHIFT)}),
              "shift+ a+ 'A' | a- | shift-");
}

TEST(InputQueue, CtrlClickHoldsCtrlThroughThePressAndRelease) {
    // xdotool "mousemove X Y keydown ctrl click 1 keyup ctrl" arriving in one go.
    EXPECT_EQ(split({move(), down(GLFW_KEY_LEFT_CONTROL), press(), release(), up(GLFW_KEY_LEFT_CONTROL)}),
              "m ctrl+ | b0+ | b0- | ctrl-");
}

TEST(InputQueue, KeysAndButtonsDoNotShareAFrame) {
    EXPECT_EQ(split({press(), down(GLFW_KEY_ENTER)}), "b0+ | ret+");
    EXPECT_EQ(split({down(GLFW_KEY_ENTER), press()}), "ret+ | b0+");
    EXPECT_EQ(split({release(), ch('x')}), "b0- | 'x'");
    EXPECT_EQ(split({wheel(), down(GLFW_KEY_X), ch('x')}), "w+1 | x+ 'x'");
}

TEST(InputQueue, ScrollStepsAreNeverLost) {
    const std::vector<InputEvent> events{move(),  wheel(), wheel(),   move(2, 2), wheel(-1),
                                         press(), wheel(), release(), wheel(),    wheel()};
    const auto frames = framesOf(events);
    EXPECT_EQ(describe(frames), "m | w+1 w+1 | m | w-1 b0+ w+1 | b0- w+1 w+1");
    double total = 0;
    for (const auto& frame : frames)
        for (const auto& e : frame)
            if (const auto* s = std::get_if<ScrollEvent>(&e)) total += s->dy;
    EXPECT_EQ(total, 4.0);
}

TEST(InputQueue, CursorMovesCoalesce) {
    InputQueue q;
    for (int i = 0; i < 1000; ++i) q.push(move(i, 2 * i));
    EXPECT_EQ(q.size(), 1u) << "a flood of motion is one event";
    const auto frame = q.takeFrame();
    ASSERT_EQ(frame.size(), 1u);
    const auto& last = std::get<CursorPosEvent>(frame[0]);
    EXPECT_EQ(last.x, 999);
    EXPECT_EQ(last.y, 1998);
    // Moves between other events stay in order; those of one frame end at the last position.
    EXPECT_EQ(split({move(), down(GLFW_KEY_A), move(), up(GLFW_KEY_A)}), "m a+ m | a-");
}

TEST(InputQueue, FocusAndDropsTakeAFrameOfTheirOwn) {
    // GLFW reports a focus loss and then releases what was held: ImGui 1.86 clears its keys in the
    // frame after a focus loss, so the press before it must be seen first.
    EXPECT_EQ(split({down(GLFW_KEY_A), FocusEvent{false}, up(GLFW_KEY_A)}), "a+ | focus- | a-");
    EXPECT_EQ(split({move(), DropEvent{{"/a.obj", "/b.obj"}}, move()}), "m | drop(2) | m");
}

TEST(InputQueue, F12PressesAreCountedOncePerPress) {
    // Three quick F12 presses: three frames that see a press (the viewer counts them).
    std::vector<InputEvent> events;
    for (int i = 0; i < 3; ++i) events.insert(events.end(), {down(GLFW_KEY_F12), up(GLFW_KEY_F12)});
    EXPECT_EQ(split(events), "f12+ | f12- | f12+ | f12- | f12+ | f12-");
}

// Random streams of everything a user does: the frames, replayed as ImGui 1.86 holds them, show
// every press and release (the stream in order, at most one transition per key and button per
// frame), every character before any editing key of its frame, no click or wheel step after a
// move in a frame nor a move after them, and every wheel step.
TEST(InputQueue, RandomStreamsLoseNothing) {
    std::mt19937 rng(32);
    const int keys[] = {GLFW_KEY_A,         GLFW_KEY_B, GLFW_KEY_ENTER, GLFW_KEY_TAB, GLFW_KEY_LEFT_CONTROL,
                        GLFW_KEY_LEFT_SHIFT};
    for (int run = 0; run < 200; ++run) {
        std::vector<InputEvent> events;
        std::set<int> held, heldButtons;
        for (int i = 0; i < 60; ++i) {
            switch (rng() % 6) {
            case 0: events.push_back(move(double(rng() % 100), double(rng() % 100))); break;
            case 1: events.push_back(wheel(rng() % 2 ? 1 : -1)); break;
            case 2: {
                const int b = int(rng() % 2);
                events.push_back(heldButtons.count(b) ? release(b) : press(b));
                if (!heldButtons.erase(b)) heldButtons.insert(b);
                break;
            }
            default: {
                const int k = keys[rng() % std::size(keys)];
                if (held.erase(k)) {
                    events.push_back(up(k));
                } else {
                    held.insert(k);
                    events.push_back(down(k));
                    if (k == GLFW_KEY_A || k == GLFW_KEY_B) events.push_back(ch(char('a' + k - GLFW_KEY_A)));
                }
            }
            }
        }
        const auto frames = framesOf(events);
        const std::string text = describe(frames);
        SCOPED_TRACE(text);
        // Concatenated, the frames are the stream, with a run of moves as its last move.
        std::vector<std::string> flat, original;
        for (const auto& f : frames)
            for (const auto& e : f) flat.push_back(std::visit(Describe{}, e));
        for (size_t i = 0; i < events.size(); ++i) {
            const bool moveRun = std::holds_alternative<CursorPosEvent>(events[i]) && i + 1 < events.size() &&
                                 std::holds_alternative<CursorPosEvent>(events[i + 1]);
            if (!moveRun) original.push_back(std::visit(Describe{}, events[i]));
        }
        ASSERT_EQ(flat, original);
        double wheelIn = 0, wheelOut = 0;
        for (const auto& e : events)
            if (const auto* w = std::get_if<ScrollEvent>(&e)) wheelIn += w->dy;
        for (const auto& frame : frames) {
            ASSERT_FALSE(frame.empty());
            std::multiset<int> keyTransitions, buttonTransitions;
            bool chars = false, editingKey = false, moved = false, pointerAction = false;
            for (size_t i = 0; i < frame.size(); ++i) {
                const InputEvent& e = frame[i];
                if (const auto* k = std::get_if<KeyEvent>(&e)) {
                    keyTransitions.insert(k->key);
                    const bool typesChar = i + 1 < frame.size() && std::holds_alternative<CharEvent>(frame[i + 1]);
                    if (k->action == kPress && !isModifierKey(k->key) && !typesChar) {
                        EXPECT_FALSE(chars) << "an editing key after characters";
                        editingKey = true;
                    }
                } else if (std::holds_alternative<CharEvent>(e)) {
                    EXPECT_FALSE(editingKey) << "a character after an editing key";
                    chars = true;
                } else if (const auto* b = std::get_if<MouseButtonEvent>(&e)) {
                    buttonTransitions.insert(b->button);
                    EXPECT_FALSE(moved) << "a click after a move";
                    pointerAction = true;
                } else if (std::holds_alternative<ScrollEvent>(e)) {
                    EXPECT_FALSE(moved) << "the wheel after a move";
                    pointerAction = true;
                } else if (std::holds_alternative<CursorPosEvent>(e)) {
                    EXPECT_FALSE(pointerAction) << "a move after a click or the wheel";
                    moved = true;
                }
            }
            for (const int k : keyTransitions) EXPECT_EQ(keyTransitions.count(k), 1u) << "key " << k;
            for (const int b : buttonTransitions) EXPECT_EQ(buttonTransitions.count(b), 1u) << "button " << b;
            for (const auto& e : frame)
                if (const auto* w = std::get_if<ScrollEvent>(&e)) wheelOut += w->dy;
        }
        EXPECT_EQ(wheelOut, wheelIn);
    }
}
