// The interactive viewer: one scene from the registry running live in a GLFW window, drawn by
// the one Renderer, with a Dear ImGui control panel on the right.
//
//   +--------------------------------------+-------------+
//   |                                      | scene list  |
//   |   the scene (Renderer::draw into     | run / step  |
//   |   the window, bottom-left corner)    | sliders     |
//   |                                      | toggles     |
//   |                                      | energy plot |
//   +--------------------------------------+-------------+
//
// Side by side (task 7's scenes, --side-by-side or the panel's checkbox): the scene area holds
// two views of the same scene, run in lockstep with the same parameters, symplectic Euler (task
// 3) on the left and implicit Euler (task 7) on the right; the energy plot shows both totals.
//
// Design notes
// - The scene area sits at the window's left edge and spans its height, so Renderer::draw's
//   viewport (0, 0, w, h) is exactly that area, and its pixels are the headless renderer's (side
//   by side: (0, 0, w/2, h) and (w/2, 0, w - w/2, h), each a headless render of its size).
// - Student code runs in makeScene, reset, advanceFrame and the mouse calls: every call is
//   guarded, an exception pauses the scene and shows its message in the panel.
// - Frames are paced to real time (one frame every params.dt seconds, at most a few per
//   display refresh); with --frames they are not paced at all, so a run is reproducible.
#pragma once

#include <chrono>
#include <memory>
#include <string>

#include "contexts/glfw_context.h"
#include "render/render_options.h"
#include "render/renderer.h"
#include "scenes/scene.h"
#include "viewer/plot.h"
#include "viewer/viewer_options.h"

namespace a6::viewer {

class Viewer {
 public:
  explicit Viewer(Options options);
  ~Viewer();
  Viewer(const Viewer&) = delete;
  Viewer& operator=(const Viewer&) = delete;

  /// Opens the window and runs until it is closed (or, with --frames, until the screenshot is
  /// saved). Returns the process exit code: 0, or 1 with the reason on stderr.
  int run();

 private:
  // Setting up.
  bool open();
  void close();

  // The scene: every call into student code goes through these, which catch what it throws.
  void loadScene(const std::string& name);
  void resetScene(const SceneParams& params);
  void applyParams(const SceneParams& params);
  bool advance();
  void fail(const std::string& what, const std::string& message);

  // Side by side: the twin is the scene again with the other integrator.
  void resetTwin();
  void recordEnergy();
  SceneParams twinParams() const;
  int views() const { return twin_ ? 2 : 1; }
  Scene& viewScene(int k) const;  ///< 0: left (symplectic when side by side), 1: right
  const Snapshot& viewSnapshot(int k) const;
  int viewLeft(int k) const;  ///< framebuffer pixels
  int viewWidth(int k) const;
  void drawViewLabels();

  // One display frame.
  void handleMouse();
  void simulate();
  void drawScene();
  void drawPanel();
  void sceneSection();
  void simulationSection();
  void parameterSection();
  bool integratorControls(SceneParams& p);  ///< true when it reset the scene
  void displaySection();
  void energySection();
  void timingSection();

  // Keys (GLFW callback, chained after ImGui's).
  static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);
  void key(int key, int mods);

  // Screenshots.
  bool saveScene(const std::string& path);
  bool saveWindow(const std::string& path);
  std::string nextScreenshotPath(const char* suffix) const;

  // The scene area in framebuffer pixels, and the panel's width in window coordinates.
  int sceneWidth() const;
  int sceneHeight() const;
  float panelWidth() const;

  Options options_;
  std::unique_ptr<GlfwContext> context_;
  std::unique_ptr<Renderer> renderer_;
  bool imgui_ = false;  ///< ImGui context and backends are initialised

  std::unique_ptr<Scene> scene_;
  std::string sceneName_;
  SceneParams params_;  ///< what the sliders show (= scene_->params() unless it failed)
  RenderOptions render_;
  Snapshot snapshot_;  ///< the picture drawn last

  bool sideBySide_ = false;      ///< asked for; a twin exists only in scenes with the switch
  std::unique_ptr<Scene> twin_;  ///< the scene with the other integrator, side by side
  Snapshot twinSnapshot_;
  History twinTotal_;
  int grabbedView_ = 0;

  bool running_ = true;
  int stepRequests_ = 0;  ///< single steps asked for while paused
  double pending_ = 0;    ///< real time not simulated yet, s
  std::chrono::steady_clock::time_point lastTick_;

  bool panelVisible_ = true;
  bool mouseWasDown_ = false;
  bool grabbing_ = false;

  History kinetic_, potential_, total_;
  bool energyLog_ = false;
  bool energyLogAuto_ = false;  ///< the log scale was switched on by an explosion
  History simulateMs_, drawMs_;
  double lastDrawMs_ = 0;
  int draws_ = 0;

  std::string error_;   ///< student code threw: shown in red, the scene is paused
  std::string status_;  ///< last screenshot saved, etc.
  bool saveSceneRequest_ = false, saveWindowRequest_ = false;
  int screenshotCounter_ = 0;
};

}  // namespace a6::viewer
