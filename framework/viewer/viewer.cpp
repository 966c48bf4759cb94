#include "viewer/viewer.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <thread>
#include <utility>

#include "image/image.h"
#include "render/palette.h"
#include "render/view_transform.h"

#ifndef A6_VIEWER_STUDENT
#define A6_VIEWER_STUDENT "?"
#endif

namespace a6::viewer {
namespace {

constexpr float kPanelWidth = 390;  // window coordinates
constexpr int kMaxFramesPerRefresh = 4;
constexpr int kMaxRefreshRate = 120;  // Hz

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Runs student code; returns the exception's message, or an empty string.
template <typename F>
std::string guarded(F&& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what()[0] ? e.what() : "an exception with no message";
  } catch (...) {
    return "an exception that is not a std::exception";
  }
  return "";
}

bool sameParams(const SceneParams& a, const SceneParams& b) {
  return a.ks == b.ks && a.kd == b.kd && a.substeps == b.substeps && a.n == b.n && a.dt == b.dt &&
         a.gravity == b.gravity && a.drag == b.drag && a.buoyancy == b.buoyancy &&
         a.structural == b.structural && a.shear == b.shear && a.bending == b.bending &&
         a.seed == b.seed && a.implicit == b.implicit;
}

ImVec4 toImGui(Rgba c) { return ImVec4(c.r / 255.0f, c.g / 255.0f, c.b / 255.0f, 1.0f); }

// A slider for a double on a logarithmic scale from lo to hi (lo may be 0), with a unit.
bool sliderDouble(const char* label, double* value, double lo, double hi, const char* format,
                  bool logarithmic, const char* help) {
  const bool changed = ImGui::SliderScalar(label, ImGuiDataType_Double, value, &lo, &hi, format,
                                           logarithmic ? ImGuiSliderFlags_Logarithmic : 0);
  if (help && ImGui::IsItemHovered()) ImGui::SetTooltip("%s\n(Ctrl+click to type a value)", help);
  return changed;
}

// The springs' sliders the scene uses: ks, kd, substeps. Ranges around the scene's defaults: a
// hundred times either way on a log scale.
void springControls(unsigned uses, const SceneParams& defaults, SceneParams& p) {
  const double ks0 = std::max(defaults.ks, 1.0);
  if (uses & kUsesKs) {
    sliderDouble("ks (N/m)", &p.ks, ks0 * 0.01, ks0 * 100, "%.4g", true,
                 "Spring stiffness ks (cloth: structural; shear and bending keep their ratio)");
  }
  if (uses & kUsesKd) {
    sliderDouble("kd (N s/m)", &p.kd, 0.0, std::max(defaults.kd * 100, 10.0), "%.4g", true,
                 "Spring damping kd, along the spring");
  }
  if (uses & kUsesSubsteps) {
    ImGui::SliderInt("substeps", &p.substeps, 1, 200, "%d", ImGuiSliderFlags_Logarithmic);
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip("Steps per frame: each step is dt / substeps. Stiff springs need more.");
    }
  }
}

// The rest the scene uses: frame time, cloth size, the world's forces, spring types, seed.
void worldControls(unsigned uses, const SceneParams& defaults, SceneParams& p) {
  if (uses & kUsesDt) {
    sliderDouble("dt (s)", &p.dt, 0.001, 0.1, "%.4f", true,
                 "Duration of one frame; one frame is simulated per frame shown");
  }
  if (uses & kUsesN) {
    ImGui::SliderInt("n (cells)", &p.n, 1, 60);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Cloth resolution: n x n cells (resets)");
  }
  if (uses & kUsesGravity) {
    sliderDouble("gravity (m/s²)", &p.gravity, 0.0, 30.0, "%.2f", false,
                 "Magnitude of g, along -y");
  }
  if (uses & kUsesDrag) {
    sliderDouble("drag (N s/m)", &p.drag, 0.0, std::max(defaults.drag * 100, 1.0), "%.4g", true,
                 "Drag coefficient: f = -k_d v");
  }
  if (uses & kUsesBuoyancy) {
    sliderDouble("buoyancy (N/K)", &p.buoyancy, 0.0, std::max(defaults.buoyancy * 10, 1e-3), "%.3g",
                 true, "Buoyancy coefficient: f = b (T - T_air) (0, 1)");
  }
  if (uses & kUsesSpringTypes) {
    ImGui::Text("Build with:");
    ImGui::SameLine();
    ImGui::Checkbox("structural", &p.structural);
    ImGui::SameLine();
    ImGui::Checkbox("shear", &p.shear);
    ImGui::SameLine();
    ImGui::Checkbox("bending", &p.bending);
  }
  if (uses & kUsesSeed) {
    ImGui::InputScalar("seed", ImGuiDataType_U64, &p.seed);
  }
}

}  // namespace

Viewer::Viewer(Options options) : options_(std::move(options)) {
  panelVisible_ = options_.gui;
  running_ = !options_.paused;
  sideBySide_ = options_.sideBySide;
}

Viewer::~Viewer() { close(); }

bool Viewer::open() {
  GlfwContext::Options o;
  o.width = options_.width + (options_.gui ? static_cast<int>(kPanelWidth) : 0);
  o.height = options_.height;
  o.title = "Assignment 6 viewer (" + std::string(A6_VIEWER_STUDENT) + ")";
  o.vsync = options_.vsync && options_.frames < 0;
  GlfwContext::Result window = GlfwContext::create(o);
  if (!window) {
    std::fprintf(stderr, "a6_viewer: %s\n", window.error.c_str());
    return false;
  }
  context_ = std::move(window.context);
  renderer_ = std::make_unique<Renderer>(*context_);
  if (!renderer_->ok()) {
    std::fprintf(stderr, "a6_viewer: %s\n", renderer_->error().c_str());
    return false;
  }
  glfwSetWindowUserPointer(context_->window(), this);
  // Installed before ImGui's: its GLFW backend calls ours after its own.
  glfwSetKeyCallback(context_->window(), onKey);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini in the student's folder
  // A font with Greek letters and math signs (the scene descriptions use ω, π, ×) if Debian's
  // fonts-dejavu-core is there; else ImGui's built-in font, which shows them as '?'.
  static const ImWchar kGlyphs[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2010, 0x205E,
                                    0x2190, 0x21FF, 0x2200, 0x22FF, 0};
  for (const char* font :
       {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "/usr/share/fonts/TTF/DejaVuSans.ttf"}) {
    if (std::FILE* f = std::fopen(font, "rb")) {
      std::fclose(f);
      if (io.Fonts->AddFontFromFileTTF(font, 15.0f, nullptr, kGlyphs)) break;
    }
  }
  ImGui::StyleColorsDark();
  ImGui::GetStyle().WindowRounding = 0;
  ImGui::GetStyle().Colors[ImGuiCol_WindowBg].w = 1.0f;
  if (!ImGui_ImplGlfw_InitForOpenGL(context_->window(), true) ||
      !ImGui_ImplOpenGL3_Init("#version 330 core")) {
    std::fprintf(stderr, "a6_viewer: Dear ImGui's GLFW / OpenGL 3 backends failed to start\n");
    return false;
  }
  imgui_ = true;
  std::printf("a6_viewer: %s, student files: %s\n", context_->description().c_str(),
              A6_VIEWER_STUDENT);
  return true;
}

void Viewer::close() {
  if (imgui_) {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    imgui_ = false;
  }
  scene_.reset();
  renderer_.reset();
  context_.reset();
}

// ---------------------------------------------------------------------------------------------
// The scene

void Viewer::fail(const std::string& what, const std::string& message) {
  error_ = what + ": " + message;
  running_ = false;
  stepRequests_ = 0;
  grabbing_ = false;
  std::fprintf(stderr, "a6_viewer: %s\n", error_.c_str());
}

void Viewer::loadScene(const std::string& name) {
  sceneName_ = name;
  scene_.reset();
  resetScene(defaultParams(name));
}

void Viewer::resetScene(const SceneParams& params) {
  params_ = params;
  error_.clear();
  grabbing_ = false;
  twin_.reset();
  twinTotal_.clear();
  pending_ = 0;
  kinetic_.clear(), potential_.clear(), total_.clear();
  simulateMs_.clear(), drawMs_.clear();
  if (energyLogAuto_) energyLog_ = energyLogAuto_ = false;
  if (!scene_) {  // a new scene, or one whose building failed last time
    std::unique_ptr<Scene> scene;
    const std::string message = guarded([&] { scene = makeScene(sceneName_); });
    if (!message.empty()) return fail("building " + sceneName_, message);
    if (!scene) return fail("building " + sceneName_, "no such scene (see --list)");
    scene_ = std::move(scene);
  }
  const std::string message = guarded([&] { scene_->reset(params); });
  if (!message.empty()) return fail("resetting " + sceneName_, message);
  params_ = scene_->params();
  // The new scene's view, for the mouse, before its first frame is drawn.
  guarded([&] { snapshot_ = scene_->snapshot(); });
  resetTwin();
  recordEnergy();
}

// This frame's energies into the plot's histories: the scene's, and the twin's total.
void Viewer::recordEnergy() {
  SceneEnergy e;
  if (scene_ && guarded([&] { e = scene_->energy(); }).empty()) {
    kinetic_.push(e.kinetic), potential_.push(e.potential), total_.push(e.total());
  }
  if (twin_ && guarded([&] { e = twin_->energy(); }).empty()) twinTotal_.push(e.total());
}

SceneParams Viewer::twinParams() const {
  SceneParams p = params_;
  p.implicit = !p.implicit;
  return p;
}

// The twin, from frame 0 like the scene, where side by side is asked for and the scene has the
// integrator switch.
void Viewer::resetTwin() {
  twin_.reset();
  twinTotal_.clear();
  const SceneInfo* info = sceneInfo(sceneName_);
  if (!sideBySide_ || !scene_ || !error_.empty() || !info || !(info->uses & kUsesIntegrator)) {
    return;
  }
  std::unique_ptr<Scene> twin;
  const std::string message = guarded([&] {
    twin = makeScene(sceneName_);
    if (twin) twin->reset(twinParams());
  });
  if (!message.empty() || !twin) {
    return fail("building " + sceneName_ + " with the other integrator", message);
  }
  twin_ = std::move(twin);
  guarded([&] { twinSnapshot_ = twin_->snapshot(); });
}

void Viewer::applyParams(const SceneParams& params) {
  if (!scene_ || !error_.empty()) {
    resetScene(params);
    return;
  }
  bool tuned = false;
  const std::string message = guarded([&] { tuned = scene_->tune(params); });
  if (!message.empty()) {
    fail("changing the parameters", message);
  } else if (tuned && !twin_) {
    params_ = scene_->params();
  } else {               // side by side, every change restarts both from frame 0, to compare them
    resetScene(params);  // n, the spring sets or the seed: the scene must be rebuilt
  }
}

bool Viewer::advance() {
  if (!scene_ || !error_.empty()) return false;
  const Clock::time_point start = Clock::now();
  const std::string message = guarded([&] { scene_->advanceFrame(); });
  if (!message.empty()) {
    fail("frame " + std::to_string(scene_->frame() + 1), message);
    return false;
  }
  if (twin_) {
    const std::string twinMessage = guarded([&] { twin_->advanceFrame(); });
    if (!twinMessage.empty()) {
      fail("frame " + std::to_string(twin_->frame() + 1) + " with the other integrator",
           twinMessage);
      return false;
    }
  }
  if (draws_ > 2) {  // the first draws compile llvmpipe's shaders: their spike would set the scale
    simulateMs_.push(millisecondsSince(start));
    drawMs_.push(lastDrawMs_);
  }
  recordEnergy();
  return true;
}

// ---------------------------------------------------------------------------------------------
// One display frame

int Viewer::sceneWidth() const {
  // The panel's width is in window coordinates; the framebuffer may have more pixels (high DPI).
  int ww = 1, wh = 1;
  glfwGetWindowSize(context_->window(), &ww, &wh);
  const double scale = static_cast<double>(context_->width()) / std::max(ww, 1);
  const int panel = panelVisible_ ? static_cast<int>(std::lround(panelWidth() * scale)) : 0;
  return context_->width() - panel;
}

int Viewer::sceneHeight() const { return context_->height(); }

Scene& Viewer::viewScene(int k) const {
  if (!twin_) return *scene_;
  const bool sceneOnLeft = !params_.implicit;
  return (k == 0) == sceneOnLeft ? *scene_ : *twin_;
}

const Snapshot& Viewer::viewSnapshot(int k) const {
  return &viewScene(k) == scene_.get() ? snapshot_ : twinSnapshot_;
}

int Viewer::viewLeft(int k) const { return k == 0 ? 0 : sceneWidth() / 2; }

int Viewer::viewWidth(int k) const {
  if (!twin_) return sceneWidth();
  return k == 0 ? sceneWidth() / 2 : sceneWidth() - sceneWidth() / 2;
}

float Viewer::panelWidth() const { return kPanelWidth; }

void Viewer::handleMouse() {
  GLFWwindow* window = context_->window();
  const bool down = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
  const bool pressed = down && !mouseWasDown_;
  mouseWasDown_ = down;
  if (!scene_ || !error_.empty()) {
    grabbing_ = false;
    return;
  }

  // The cursor, window coordinates -> framebuffer pixels -> world (the view of the last picture).
  double cx = 0, cy = 0;
  glfwGetCursorPos(window, &cx, &cy);
  int ww = 1, wh = 1;
  glfwGetWindowSize(window, &ww, &wh);
  const Vec2 pixel(cx * context_->width() / std::max(ww, 1),
                   cy * context_->height() / std::max(wh, 1));
  const int w = sceneWidth(), h = sceneHeight();
  if (w <= 0 || h <= 0) return;
  const bool overScene = pixel.x() >= 0 && pixel.x() < w && pixel.y() >= 0 && pixel.y() < h &&
                         !(panelVisible_ && ImGui::GetIO().WantCaptureMouse);
  // Side by side, the view pressed in is the one dragged until the button is released.
  if (pressed) grabbedView_ = views() == 2 && pixel.x() >= viewLeft(1) ? 1 : 0;
  const int k = grabbedView_;
  Scene& scene = viewScene(k);
  const Vec2 world =
      ViewTransform(viewSnapshot(k).view, viewWidth(k), h).toWorld(pixel - Vec2(viewLeft(k), 0));

  std::string message;
  if (pressed && overScene) {
    message = guarded([&] { grabbing_ = scene.grab(world); });
  } else if (down && grabbing_) {
    message = guarded([&] { scene.drag(world); });
  } else if (!down && grabbing_) {
    grabbing_ = false;
    message = guarded([&] { scene.release(); });
  }
  if (!message.empty()) fail("dragging with the mouse", message);
}

void Viewer::simulate() {
  const Clock::time_point now = Clock::now();
  const double elapsed = std::chrono::duration<double>(now - lastTick_).count();
  lastTick_ = now;
  if (!scene_ || !error_.empty()) return;

  if (options_.frames >= 0) {  // reproducible run: one frame per display frame, no pacing
    if (scene_->frame() < options_.frames) advance();
    return;
  }
  if (running_) {
    // Real time: a frame every dt seconds. Rounding to the nearest frame (not flooring) keeps
    // one frame per refresh when the display runs at 1/dt and its timing jitters.
    const double dt = scene_->params().dt;
    pending_ += std::min(elapsed, 0.25);
    int frames = 0;
    while (pending_ >= 0.5 * dt && frames < kMaxFramesPerRefresh && advance()) {
      pending_ -= dt;
      ++frames;
    }
    if (frames == kMaxFramesPerRefresh) pending_ = 0;  // slower than real time: slow motion
  } else {
    pending_ = 0;
    for (; stepRequests_ > 0; --stepRequests_) advance();
  }
}

void Viewer::drawScene() {
  const GLFunctions& gl = renderer_->gl();
  gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
  if (scene_) {
    const std::string message = guarded([&] { snapshot_ = scene_->snapshot(); });
    if (!message.empty()) fail("taking a snapshot", message);
  } else {
    snapshot_ = Snapshot();
  }
  if (twin_) {
    const std::string message = guarded([&] { twinSnapshot_ = twin_->snapshot(); });
    if (!message.empty()) fail("taking a snapshot with the other integrator", message);
  }
  const int w = sceneWidth(), h = sceneHeight();
  if (w <= 0 || h <= 0) {
    const Rgba bg = palette::kBackground;
    gl.ClearColor(bg.r / 255.0f, bg.g / 255.0f, bg.b / 255.0f, 1.0f);
    gl.Clear(GL_COLOR_BUFFER_BIT);
    return;
  }
  const Clock::time_point start = Clock::now();
  for (int k = 0; k < (scene_ ? views() : 1); ++k) {
    const Snapshot& shot = scene_ ? viewSnapshot(k) : snapshot_;
    if (!renderer_->draw(shot, viewWidth(k), h, render_, viewLeft(k))) status_ = renderer_->error();
  }
  gl.Finish();  // so the time measured is the drawing's, not just its submission's
  lastDrawMs_ = millisecondsSince(start);
  ++draws_;
}

int Viewer::run() {
  if (!open()) return 1;
  loadScene(options_.scene);
  lastTick_ = Clock::now();
  GLFWwindow* window = context_->window();
  int exitCode = 0;
  while (!glfwWindowShouldClose(window)) {
    const Clock::time_point frameStart = Clock::now();
    glfwPollEvents();
    const bool gui = panelVisible_;
    if (gui) {
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();
    }
    handleMouse();
    simulate();
    drawScene();
    if (gui) {
      drawPanel();
      drawViewLabels();
      if (grabbing_) {  // a ring at the cursor while something is held
        ImGui::GetForegroundDrawList()->AddCircle(ImGui::GetIO().MousePos, 9,
                                                  IM_COL32(220, 40, 30, 255), 0, 2);
      }
      ImGui::Render();
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    }

    // Screenshots of this frame, read before the swap.
    if (options_.frames >= 0 &&
        (!error_.empty() || (scene_ && scene_->frame() >= options_.frames))) {
      const std::string path =
          options_.screenshot.empty()
              ? sceneName_ + "_frame" + std::to_string(options_.frames) + ".png"
              : options_.screenshot;
      if (!saveWindow(path)) exitCode = 1;
      if (!error_.empty()) exitCode = 1;
      std::printf("a6_viewer: %s at frame %d (t = %.4f s): %s\n", sceneName_.c_str(),
                  scene_ ? scene_->frame() : 0, scene_ ? scene_->time() : 0.0, status_.c_str());
      break;
    }
    if (saveWindowRequest_) saveWindow(nextScreenshotPath("_window"));
    if (saveSceneRequest_) saveScene(nextScreenshotPath(""));
    saveWindowRequest_ = saveSceneRequest_ = false;
    glfwSwapBuffers(window);
    // Without vsync (Xvfb, some drivers) the loop would spin: at most kMaxRefreshRate frames/s.
    if (options_.frames < 0) {
      std::this_thread::sleep_until(frameStart +
                                    std::chrono::microseconds(1000000 / kMaxRefreshRate));
    }
  }
  close();
  return exitCode;
}

// Side by side: each view's integrator over it, and a line between the two.
void Viewer::drawViewLabels() {
  if (!twin_) return;
  int ww = 1, wh = 1;
  glfwGetWindowSize(context_->window(), &ww, &wh);
  const float scale = static_cast<float>(ww) / std::max(context_->width(), 1);  // fb -> window
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  const float middle = viewLeft(1) * scale;
  draw->AddLine(ImVec2(middle, 0), ImVec2(middle, static_cast<float>(wh)),
                IM_COL32(90, 90, 90, 255), 2);
  const int substeps = params_.substeps;
  for (int k = 0; k < 2; ++k) {
    const bool implicit = viewScene(k).params().implicit;
    const std::string label =
        std::string(implicit ? "implicit Euler (task 7), " : "symplectic Euler (task 3), ") +
        std::to_string(substeps) + (substeps == 1 ? " step" : " steps") + " per frame";
    draw->AddText(ImVec2(viewLeft(k) * scale + 8, 6), IM_COL32(40, 40, 40, 255), label.c_str());
  }
}

// ---------------------------------------------------------------------------------------------
// The panel

void Viewer::drawPanel() {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - panelWidth(), 0));
  ImGui::SetNextWindowSize(ImVec2(panelWidth(), io.DisplaySize.y));
  ImGui::Begin("a6", nullptr,
               ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                   ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoBringToFrontOnFocus);
  ImGui::PushItemWidth(-130);  // room for the labels
  sceneSection();
  simulationSection();
  energySection();
  parameterSection();
  displaySection();
  timingSection();
  ImGui::PopItemWidth();
  ImGui::End();
}

void Viewer::sceneSection() {
  ImGui::Text("Assignment 6: particles and springs");
  ImGui::TextDisabled("student files: %s", A6_VIEWER_STUDENT);
  const SceneInfo* current = sceneInfo(sceneName_);
  const std::string title = current ? current->title : sceneName_;
  ImGui::SetNextItemWidth(-1);
  if (ImGui::BeginCombo("##scene", title.c_str(), ImGuiComboFlags_HeightLarge)) {
    for (const std::string& name : sceneNames()) {
      const SceneInfo* info = sceneInfo(name);
      const std::string label = "Task " + std::to_string(info->task) + "  " + info->title;
      if (ImGui::Selectable(label.c_str(), name == sceneName_)) loadScene(name);
      if (ImGui::IsItemHovered()) {
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 28);
        ImGui::TextUnformatted((name + ": " + info->description).c_str());
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
      }
      if (name == sceneName_) ImGui::SetItemDefaultFocus();
    }
    ImGui::EndCombo();
  }
  if (current) ImGui::TextWrapped("%s", current->description.c_str());
}

void Viewer::simulationSection() {
  ImGui::Separator();
  if (ImGui::Button(running_ ? "Pause" : " Run ", ImVec2(60, 0))) running_ = !running_;
  ImGui::SameLine();
  if (ImGui::Button("Step")) {
    running_ = false;
    ++stepRequests_;
  }
  ImGui::SameLine();
  if (ImGui::Button("Reset")) resetScene(params_);
  ImGui::SameLine();
  if (ImGui::Button("Defaults")) resetScene(defaultParams(sceneName_));
  if (scene_) {
    ImGui::Text("t = %.3f s   frame %d   %s", scene_->time(), scene_->frame(),
                running_ ? "running" : "paused");
    ImGui::TextDisabled("%zu particles, %zu springs, %zu shapes, %zu joints",
                        snapshot_.particles.size(), snapshot_.springs.size(),
                        snapshot_.shapes.size(), snapshot_.joints.size());
  }
  if (scene_ && error_.empty() && scene_->frame() > 0 && snapshot_.particles.empty() &&
      snapshot_.shapes.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.8f, 0.3f, 1.0f));
    ImGui::TextWrapped(
        "Nothing to draw: this scene's particles come from the student code "
        "(task %d), which has not made any yet.",
        scene_->info().task);
    ImGui::PopStyleColor();
  }
  if (!error_.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
    ImGui::TextWrapped("%s", error_.c_str());
    ImGui::PopStyleColor();
    ImGui::TextDisabled("Fix the code, rebuild and restart the viewer; Reset tries again.");
  }
}

void Viewer::parameterSection() {
  const SceneInfo* info = sceneInfo(sceneName_);
  if (!info || !ImGui::CollapsingHeader("Parameters", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const unsigned uses = info->uses;
  const SceneParams defaults = defaultParams(sceneName_);
  SceneParams p = params_;
  springControls(uses, defaults, p);
  if ((uses & kUsesIntegrator) && integratorControls(p)) return;
  worldControls(uses, defaults, p);
  if (!sameParams(p, params_)) applyParams(p);
}

bool Viewer::integratorControls(SceneParams& p) {
  // Task 7: switch the running scene between task 3's step and task 7's stepImplicit, and
  // watch the energy plot: symplectic Euler keeps it (or explodes), implicit Euler damps it.
  int integrator = p.implicit ? 1 : 0;
  ImGui::Text("Integrator:");
  ImGui::SameLine();
  ImGui::RadioButton("symplectic (task 3)", &integrator, 0);
  ImGui::SameLine();
  ImGui::RadioButton("implicit (task 7)", &integrator, 1);
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("stepImplicit: one backward Euler step per substep, stable at any dt");
  }
  p.implicit = integrator == 1;
  // Both at once: the twin runs the other integrator beside the scene, from frame 0.
  if (ImGui::Checkbox("side by side", &sideBySide_)) {
    resetScene(p);
    return true;
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("The scene twice: symplectic Euler left, implicit Euler right");
  }
  return false;
}

void Viewer::displaySection() {
  if (!ImGui::CollapsingHeader("Display", ImGuiTreeNodeFlags_DefaultOpen)) return;
  // One toggle per spring type, in its colour.
  const struct {
    SpringType type;
    const char* label;
    Rgba color;
  } types[] = {{SpringType::Structural, "structural", palette::kStructural},
               {SpringType::Shear, "shear", palette::kShear},
               {SpringType::Bending, "bending", palette::kBending},
               {SpringType::Other, "other", palette::kOtherSpring}};
  // Only what the scene has.
  if (!snapshot_.springs.empty()) {
    ImGui::TextDisabled("show springs");
    for (const auto& t : types) {
      if (t.type != SpringType::Structural) ImGui::SameLine();
      bool visible = render_.springVisible(t.type);
      ImGui::PushStyleColor(ImGuiCol_CheckMark, toImGui(t.color));
      ImGui::PushStyleColor(ImGuiCol_FrameBg,
                            toImGui(palette::mix(t.color, Rgba{40, 40, 40, 255}, 0.6)));
      if (ImGui::Checkbox(t.label, &visible)) render_.setSpringVisible(t.type, visible);
      ImGui::PopStyleColor(2);
    }
    ImGui::Checkbox("colour springs by strain", &render_.colorSpringsByStrain);
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip("(l - l0) / l0: blue compressed, grey at rest, red stretched");
    }
    if (render_.colorSpringsByStrain) {
      sliderDouble("full colour at", &render_.strainForFullColor, 0.001, 1.0, "%.3f", true,
                   "The strain |l - l0| / l0 drawn in full red or blue");
    }
  }
  bool first = true;
  auto toggle = [&](bool present, const char* label, bool* value) {
    if (!present) return;
    if (!first) ImGui::SameLine();
    first = false;
    ImGui::Checkbox(label, value);
  };
  toggle(!snapshot_.particles.empty(), "particles", &render_.showParticles);
  toggle(!snapshot_.planes.empty() || !snapshot_.circles.empty(), "obstacles",
         &render_.showObstacles);
  toggle(!snapshot_.shapes.empty(), "shapes", &render_.showShapes);
  toggle(!snapshot_.joints.empty(), "joints", &render_.showJoints);
  if (ImGui::Button("Save scene PNG (S)")) saveSceneRequest_ = true;
  ImGui::SameLine();
  if (ImGui::Button("Save window (Shift+S)")) saveWindowRequest_ = true;
  if (!status_.empty()) ImGui::TextDisabled("%s", status_.c_str());
}

void Viewer::energySection() {
  if (!ImGui::CollapsingHeader("Energy", ImGuiTreeNodeFlags_DefaultOpen)) return;
  // An explosion (1e30 J) flattens everything else: switch to the log scale once per run.
  if (!energyLogAuto_) {
    for (const History* history : {&total_, &twinTotal_}) {
      for (float v : history->values()) {
        if (!(std::abs(v) < 1e6f)) energyLog_ = energyLogAuto_ = true;  // also NaN
      }
    }
  }
  std::vector<PlotSeries> series = {{"kinetic", &kinetic_, IM_COL32(90, 160, 255, 255)},
                                    {"potential", &potential_, IM_COL32(255, 150, 40, 255)},
                                    {"total", &total_, IM_COL32(235, 235, 235, 255)}};
  if (twin_) {  // side by side: the kinetic and potential energies are the scene's
    const bool implicit = params_.implicit;
    series[2].name = implicit ? "total, implicit" : "total, symplectic";
    series.push_back({implicit ? "total, symplectic" : "total, implicit", &twinTotal_,
                      IM_COL32(120, 220, 120, 255)});
  }
  plotLines("energy", series, 110, "J", false, energyLog_);
  ImGui::Checkbox("log scale", &energyLog_);
  ImGui::SameLine();
  ImGui::TextDisabled("(?)");
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "Potential = gravity (from y = 0) + springs (contacts, joints, mouse).\n"
        "Undamped and stable: the total stays bounded. Growing without end:\n"
        "unstable (try more substeps). Log scale: sign(E) log10(1 + |E|).");
  }
}

void Viewer::timingSection() {
  if (!ImGui::CollapsingHeader("Frame time", ImGuiTreeNodeFlags_DefaultOpen)) return;
  plotLines("timing",
            {{"simulate", &simulateMs_, IM_COL32(110, 210, 110, 255)},
             {"draw", &drawMs_, IM_COL32(200, 130, 255, 255)}},
            60, "ms", true);
}

// ---------------------------------------------------------------------------------------------
// Keys and screenshots

void Viewer::onKey(GLFWwindow* window, int key, int /*scancode*/, int action, int mods) {
  auto* viewer = static_cast<Viewer*>(glfwGetWindowUserPointer(window));
  if (viewer == nullptr || action == GLFW_RELEASE) return;
  // Repeats only for stepping; never while ImGui is typing into a field.
  if (action == GLFW_REPEAT && key != GLFW_KEY_N && key != GLFW_KEY_RIGHT) return;
  if (viewer->imgui_ && viewer->panelVisible_ && ImGui::GetIO().WantCaptureKeyboard) return;
  viewer->key(key, mods);
}

void Viewer::key(int key, int mods) {
  const std::vector<std::string>& names = sceneNames();
  const auto current = std::find(names.begin(), names.end(), sceneName_);
  const int index = static_cast<int>(current - names.begin());
  const int count = static_cast<int>(names.size());
  switch (key) {
    case GLFW_KEY_SPACE:
      running_ = !running_;
      break;
    case GLFW_KEY_N:
    case GLFW_KEY_RIGHT:
      running_ = false;
      ++stepRequests_;
      break;
    case GLFW_KEY_R:
      resetScene(params_);
      break;
    case GLFW_KEY_D:
      resetScene(defaultParams(sceneName_));
      break;
    case GLFW_KEY_S:
      (mods & GLFW_MOD_SHIFT ? saveWindowRequest_ : saveSceneRequest_) = true;
      break;
    case GLFW_KEY_LEFT_BRACKET:
      loadScene(names[(index + count - 1) % count]);
      break;
    case GLFW_KEY_RIGHT_BRACKET:
      loadScene(names[(index + 1) % count]);
      break;
    case GLFW_KEY_H:
    case GLFW_KEY_TAB:
      panelVisible_ = !panelVisible_;
      break;
    case GLFW_KEY_ESCAPE:
    case GLFW_KEY_Q:
      glfwSetWindowShouldClose(context_->window(), GLFW_TRUE);
      break;
    default:
      break;
  }
}

std::string Viewer::nextScreenshotPath(const char* suffix) const {
  const int frame = scene_ ? scene_->frame() : 0;
  return "a6_" + sceneName_ + "_" + std::to_string(frame) + suffix + ".png";
}

bool Viewer::saveScene(const std::string& path) {
  // The same renderer into an offscreen image of the scene area's size: the picture the
  // headless renderer makes of this frame, without the panel.
  const Image image = renderer_->render(snapshot_, sceneWidth(), sceneHeight(), render_);
  if (image.empty()) {
    status_ = "screenshot failed: " + renderer_->error();
    return false;
  }
  if (std::string error = writePng(image, path); !error.empty()) {
    status_ = "screenshot failed: " + error;
    return false;
  }
  status_ = "saved " + path;
  std::printf("a6_viewer: %s\n", status_.c_str());
  return true;
}

bool Viewer::saveWindow(const std::string& path) {
  // What the window shows: the back buffer, read before it is swapped.
  const GLFunctions& gl = renderer_->gl();
  const int w = context_->width(), h = context_->height();
  std::vector<std::uint8_t> rows(static_cast<std::size_t>(w) * h * 4);
  gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
  gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl.ReadBuffer(GL_BACK);
  gl.ReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
  if (GLenum e = gl.GetError(); e != GL_NO_ERROR) {
    status_ = "reading the window failed with " + glErrorName(e);
    std::fprintf(stderr, "a6_viewer: %s\n", status_.c_str());
    return false;
  }
  // OpenGL's rows go bottom-up; the window's alpha is whatever ImGui's blending left: opaque.
  Image image(w, h);
  const std::size_t stride = static_cast<std::size_t>(w) * 4;
  for (int y = 0; y < h; ++y) {
    std::memcpy(&image.pixels[y * stride], &rows[(h - 1 - y) * stride], stride);
  }
  for (std::size_t k = 3; k < image.pixels.size(); k += 4) image.pixels[k] = 255;
  if (std::string error = writePng(image, path); !error.empty()) {
    status_ = "screenshot failed: " + error;
    std::fprintf(stderr, "a6_viewer: %s\n", status_.c_str());
    return false;
  }
  status_ = "saved " + path + " (" + std::to_string(w) + "x" + std::to_string(h) + ")";
  std::printf("a6_viewer: %s\n", status_.c_str());
  return true;
}

}  // namespace a6::viewer
