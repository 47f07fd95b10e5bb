#include "imgui_setup.h"

#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cmath>

// DejaVu Sans (fonts-dejavu-core), compiled into the binary so a bundled executable needs no font
// files; its path comes from CMake.
__asm__(".section .rodata\n"
        ".balign 16\n"
        ".global shadowscope_font_begin\n.hidden shadowscope_font_begin\n"
        ".global shadowscope_font_end\n.hidden shadowscope_font_end\n"
        "shadowscope_font_begin:\n"
        ".incbin \"" SHADOWSCOPE_FONT_PATH "\"\n"
        "shadowscope_font_end:\n"
        ".byte 0\n"
        ".previous\n");
extern "C" {
extern const unsigned char shadowscope_font_begin[];
extern const unsigned char shadowscope_font_end[];
}

namespace ui {

float clampUiScale(float s) noexcept { return std::isfinite(s) && s > 0.f ? std::clamp(s, 1.f, 4.f) : 1.f; }

ImGuiScope::ImGuiScope(float uiScale) : scale_(clampUiScale(uiScale)) {
    IMGUI_CHECKVERSION();
    context_ = ImGui::CreateContext();
    ImGui::SetCurrentContext(context_);
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr; // the layout lives in the dashboard's own config file
    io.LogFilename = nullptr;
    applyStyleAndFonts();
    ImGui_ImplOpenGL3_Init("#version 430 core");
}

ImGuiScope::~ImGuiScope() {
    ImGuiContext* previous = ImGui::GetCurrentContext();
    ImGui::SetCurrentContext(context_);
    ImGui_ImplOpenGL3_Shutdown();
    ImGui::DestroyContext(context_);
    ImGui::SetCurrentContext(previous == context_ ? nullptr : previous);
}

void ImGuiScope::makeCurrent() const noexcept { ImGui::SetCurrentContext(context_); }

void ImGuiScope::rescale(float uiScale) {
    const float s = clampUiScale(uiScale);
    if (s == scale_) return;
    makeCurrent();
    scale_ = s;
    applyStyleAndFonts();
    ImGui_ImplOpenGL3_DestroyFontsTexture();
    ImGui_ImplOpenGL3_CreateFontsTexture();
}

void ImGuiScope::applyStyleAndFonts() {
    ImGuiStyle style;
    ImGui::StyleColorsDark(&style);
    style.WindowRounding = 0.f;
    style.ChildRounding = 0.f;
    style.FrameRounding = 2.f;
    style.Colors[ImGuiCol_WindowBg].w = 1.f; // opaque: the window's clear colour never shows through
    // Translucent slider grabs: every slider draws its value over the grab, which must not hide it.
    style.Colors[ImGuiCol_SliderGrab].w = style.Colors[ImGuiCol_SliderGrabActive].w = 0.45f;
    style.ScaleAllSizes(scale_);
    ImGui::GetStyle() = style;

    ImGuiIO& io = ImGui::GetIO();
    io.Fonts->Clear();
    // Latin-1, Greek (γ, α, λ, φ), punctuation (–, …), arrows, maths (∞, ≤).
    static const ImWchar ranges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2000, 0x206F, 0x2190, 0x21FF, 0x2200, 0x22FF, 0};
    ImFontConfig config;
    config.FontDataOwnedByAtlas = false; // static data
    config.OversampleH = 2;
    const int bytes = int(shadowscope_font_end - shadowscope_font_begin);
    if (bytes > 0)
        io.Fonts->AddFontFromMemoryTTF(const_cast<unsigned char*>(shadowscope_font_begin), bytes,
                                       std::round(14.f * scale_), &config, ranges);
    else io.Fonts->AddFontDefault();
}

} // namespace ui
