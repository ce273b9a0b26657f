/// @file Texture and skin files an MJCF names that MuJoCo cannot read (a robot's XML copied without
/// its assets folder: dm_control's dog). Both only draw the robot, and MuJoCo's compiler stops at the
/// first it cannot open. A texture is then read as a plain one (builtin="flat", which MuJoCo takes
/// before the file), so that the materials that name it stay; a skin is left out (nothing names a
/// skin). The dynamics are the file's: neither enters them.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace eomgen {

/// What MuJoCo 2.2.2's message says it could not read: a <texture> or a <skin>, the element's name
/// (empty when MuJoCo names none) and its file where the message gives it.
struct UnreadableDrawing {
  std::string element, name, file;
};

/// The texture or skin of MuJoCo's message, or nothing when it is about something else.
std::optional<UnreadableDrawing> unreadable_drawing(const std::string& message);

/// The texts (files by name and text) with that texture plain or that skin left out, each file it
/// named added to `files`; false when no element was changed.
bool without_unreadable_drawing(std::vector<std::pair<std::string, std::string>>& sources, const UnreadableDrawing& drawing,
                                std::vector<std::string>& files);

}  // namespace eomgen
