#include "view/input.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <sstream>

#include "error.h"

namespace vct {

void InputState::beginFrame() {
    keysPressed.clear();
    cursorDelta = glm::vec2(0.0f);
    scroll = 0.0f;
}

void InputState::key(int code, bool down) {
    if (down) {
        keysHeld.insert(code);
        keysPressed.push_back(code);
    } else {
        keysHeld.erase(code);
    }
}

void InputState::moveCursor(glm::vec2 position) {
    cursorDelta += position - cursor;
    cursor = position;
}

static InputState& stateOf(GLFWwindow* window) { return *static_cast<InputState*>(glfwGetWindowUserPointer(window)); }

void installInputCallbacks(GLFWwindow* window, InputState* state) {
    glfwSetWindowUserPointer(window, state);
    glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int) {
        if (action == GLFW_PRESS) stateOf(w).key(key, true);
        if (action == GLFW_RELEASE) stateOf(w).key(key, false);
    });
    glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int button, int action, int) {
        if (button >= 0 && button < 3) stateOf(w).buttons[button] = action == GLFW_PRESS;
    });
    glfwSetCursorPosCallback(
        window, [](GLFWwindow* w, double x, double y) { stateOf(w).moveCursor(glm::vec2(float(x), float(y))); });
    glfwSetScrollCallback(window, [](GLFWwindow* w, double, double dy) { stateOf(w).scroll += float(dy); });
    glfwSetDropCallback(window, [](GLFWwindow* w, int count, const char** paths) {
        for (int i = 0; i < count; ++i) stateOf(w).droppedFiles.emplace_back(paths[i]);
    });
}

int keyFromName(const std::string& rawName) {
    std::string name = rawName;
    std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (name.size() == 1 && std::isalpha(static_cast<unsigned char>(name[0]))) return GLFW_KEY_A + (name[0] - 'a');
    if (name.size() == 1 && std::isdigit(static_cast<unsigned char>(name[0]))) return GLFW_KEY_0 + (name[0] - '0');
    if (name.size() >= 2 && name[0] == 'f' && std::all_of(name.begin() + 1, name.end(), ::isdigit)) {
        const int number = std::stoi(name.substr(1));
        if (number >= 1 && number <= 12) return GLFW_KEY_F1 + number - 1;
    }
    static const std::map<std::string, int> named = {
        {"left", GLFW_KEY_LEFT},      {"right", GLFW_KEY_RIGHT},      {"up", GLFW_KEY_UP},
        {"down", GLFW_KEY_DOWN},      {"shift", GLFW_KEY_LEFT_SHIFT}, {"ctrl", GLFW_KEY_LEFT_CONTROL},
        {"tab", GLFW_KEY_TAB},        {"space", GLFW_KEY_SPACE},      {"escape", GLFW_KEY_ESCAPE},
        {"[", GLFW_KEY_LEFT_BRACKET}, {"]", GLFW_KEY_RIGHT_BRACKET}};
    const auto found = named.find(name);
    return found == named.end() ? -1 : found->second;
}

static size_t argumentCount(const std::string& action) {
    static const std::map<std::string, size_t> counts = {
        {"key", 2},        {"mouse", 2}, {"button", 2}, {"scroll", 1}, {"resize", 2}, {"iconify", 0}, {"restore", 0},
        {"screenshot", 1}, {"drop", 1},  {"quit", 0},   {"light", 3},  {"type", 1},   {"sky", 3}};
    const auto found = counts.find(action);
    return found == counts.end() ? size_t(-1) : found->second;
}

std::vector<ScriptEvent> parseScript(const std::string& text) {
    std::vector<ScriptEvent> events;
    std::string normalized = text;
    std::replace(normalized.begin(), normalized.end(), ';', '\n');
    std::istringstream lines(normalized);
    for (std::string line; std::getline(lines, line);) {
        line = line.substr(0, line.find('#'));
        std::istringstream words(line);
        std::string frame;
        if (!(words >> frame)) continue;
        ScriptEvent event;
        if (!std::all_of(frame.begin(), frame.end(), ::isdigit))
            throw Error("script entry '" + line + "' must start with a frame number");
        event.frame = std::stoull(frame);
        if (!(words >> event.action)) throw Error("script entry '" + line + "' names no action");
        for (std::string word; words >> word;) event.arguments.push_back(word);
        const size_t wanted = argumentCount(event.action);
        if (wanted == size_t(-1)) throw Error("script entry '" + line + "': unknown action '" + event.action + "'");
        const bool optionalUi =
            event.action == "screenshot" && event.arguments.size() == 2 && event.arguments[1] == "ui";
        if (event.arguments.size() != wanted && !optionalUi)
            throw Error("script entry '" + line + "': '" + event.action + "' takes " + std::to_string(wanted) +
                        " argument(s)");
        if (event.action == "key") {
            if (keyFromName(event.arguments[0]) < 0) throw Error("script entry '" + line + "': unknown key");
            const std::string& how = event.arguments[1];
            if (how != "down" && how != "up" && how != "press")
                throw Error("script entry '" + line + "': a key goes down, up or press");
        }
        if (event.action == "light" && event.arguments[1] != "intensity")
            throw Error("script entry '" + line + "': a light's intensity is what a script sets");
        if (event.action == "button" && event.arguments[0] != "left" && event.arguments[0] != "right")
            throw Error("script entry '" + line + "': the button is left or right");
        events.push_back(event);
    }
    std::stable_sort(events.begin(), events.end(),
                     [](const ScriptEvent& a, const ScriptEvent& b) { return a.frame < b.frame; });
    return events;
}

}  // namespace vct
