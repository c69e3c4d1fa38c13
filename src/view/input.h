// Mouse and keyboard as the viewer sees them, fed by GLFW's callbacks or by a script.
//
// A script (`vct view --events "..."` or `--script FILE`) drives the viewer without a person, for
// tests: entries separated by newlines or ';', each "FRAME ACTION ARGUMENTS", '#' starts a comment.
//   key NAME down|up|press     NAME: a letter or digit, F1..F12, left, right, up, down, shift, ctrl, tab,
//                              space, escape, [ or ]
//   mouse X Y                  move the cursor to window coordinates X, Y
//   button left|right down|up
//   scroll DY
//   resize W H | iconify | restore
//   screenshot FILE.png [ui]   the image alone (beside the open settings), or the whole window with the
//                              UI when "ui" is given
//   drop FILE                  as if FILE were dropped on the window
//   type TEXT                  TEXT as typed characters, into the text field that has the focus
//   light INDEX intensity X    what the scene panel's intensity field does to the scene's light INDEX
//   sky R G B                  what the scene panel's sky radiance field does
//                              (counted from 0, as the panel lists them; cd, or lux for the sun)
//   quit
// FRAME counts loop iterations from 0, including iterations where a minimised window draws nothing.
#pragma once

#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include <glm/glm.hpp>

struct GLFWwindow;

namespace vct {

struct InputState {
    std::set<int> keysHeld;                   // GLFW key codes
    std::vector<int> keysPressed;             // this frame, in order
    bool buttons[3] = {false, false, false};  // GLFW_MOUSE_BUTTON_LEFT, RIGHT, MIDDLE
    glm::vec2 cursor{0.0f};
    glm::vec2 cursorDelta{0.0f};  // this frame
    float scroll = 0.0f;          // this frame
    std::vector<std::string> droppedFiles;

    void beginFrame();
    bool held(int key) const { return keysHeld.count(key) > 0; }
    void key(int key, bool down);
    void moveCursor(glm::vec2 position);
};

// Routes the window's key, button, cursor, scroll and drop callbacks into `state`. Install before
// ImGui's GLFW backend, which chains to these.
void installInputCallbacks(GLFWwindow* window, InputState* state);

struct ScriptEvent {
    uint64_t frame = 0;
    std::string action;
    std::vector<std::string> arguments;
};

// Throws vct::Error naming the entry and the problem.
std::vector<ScriptEvent> parseScript(const std::string& text);

// GLFW key code for a script's key name; -1 when unknown.
int keyFromName(const std::string& name);

}  // namespace vct
