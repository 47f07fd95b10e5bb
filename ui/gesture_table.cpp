#include "gesture_table.h"

namespace ui {

const std::vector<Gesture>& gestureTable() {
    static const std::vector<Gesture> table = {
        {"Eye view", "Drag", "orbit about the target"},
        {"Eye view", "Shift+drag, middle-drag", "pan the camera"},
        {"Eye view", "Wheel", "dolly towards the target"},
        {"Eye view", "Right-drag", "look around (the eye stays)"},
        {"Eye view", "Right-drag + W A S D, Q E", "fly forward, left, back, right; down, up"},
        {"Eye view", "Double-click", "fit the camera to the scene (and the image to the panel)"},
        {"Eye view", "Ctrl+wheel", "zoom the image around the cursor"},
        {"Eye view", "Ctrl+drag", "pan the zoomed image"},
        {"Eye view, split screen", "Drag the divider", "move the border between A and B"},
        {"Every view", "Shift+click", "pin the pixel in the inspector (Stats panel)"},
        {"Light view, heatmap", "Wheel", "zoom the image around the cursor"},
        {"Light view, heatmap", "Drag, middle-drag", "pan the zoomed image"},
        {"Light view, heatmap", "Double-click", "fit the image to the panel"},
        {"Sun disc", "Drag", "the sun's azimuth (around) and elevation (centre = overhead)"},
        {"Sliders", "Drag, click", "set the value"},
        {"Sliders", "Ctrl+click", "type a value: Return applies it, Escape cancels"},
        {"Panel borders", "Drag", "resize the panels"},
        {"Window", "Drop a file", "load the scene or model file"},
        {"Keys", "F1", "this help (also the ? button)"},
        {"Keys", "F12", "screenshots into a new numbered folder (also the Screenshot button)"},
        {"Keys", "Escape", "close this help, the file browser or the export dialog"},
        {"Keys", "Ctrl+Q", "quit (the config is saved)"},
    };
    return table;
}

} // namespace ui
