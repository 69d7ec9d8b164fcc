// Frames -> MP4 through ffmpeg.
#include "impulse2d/render/video.h"

#include <unistd.h>

#include <cstdlib>
#include <sstream>
#include <string>

namespace impulse2d::render {

namespace {

/// `text` in single quotes for the POSIX shell, inner single quotes escaped.
std::string shellQuoted(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string ffmpegCommand(const std::string& ffmpeg, const FrameWriter& writer,
                          double framesPerSecond, const std::filesystem::path& video) {
  const std::filesystem::path pattern = writer.directory() / (writer.prefix() + "_%05d.png");
  std::ostringstream command;
  command << ffmpeg << " -y -loglevel error -framerate " << framesPerSecond << " -i "
          << shellQuoted(pattern.string())
          << " -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2' -c:v libx264 -pix_fmt yuv420p "
          << shellQuoted(video.string());
  return command.str();
}

}  // namespace

std::optional<std::filesystem::path> findFfmpeg() {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return std::nullopt;
  std::istringstream directories(path);
  std::string directory;
  while (std::getline(directories, directory, ':')) {
    if (directory.empty()) continue;
    const std::filesystem::path candidate = std::filesystem::path(directory) / "ffmpeg";
    if (access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return std::nullopt;
}

std::filesystem::path writeVideo(const FrameWriter& writer, double framesPerSecond) {
  const std::filesystem::path video = writer.directory() / (writer.prefix() + ".mp4");
  const std::optional<std::filesystem::path> ffmpeg = findFfmpeg();
  const std::string byHand = ffmpegCommand("ffmpeg", writer, framesPerSecond, video);
  if (!ffmpeg) {
    throw RenderError("ffmpeg is not on PATH, so no video was made; the frames are in '" +
                      writer.directory().string() + "'. With ffmpeg installed, run: " + byHand);
  }
  if (writer.frameCount() == 0) {
    throw RenderError("no frames in '" + writer.directory().string() + "' to make a video of");
  }
  const std::string command =
      ffmpegCommand(shellQuoted(ffmpeg->string()), writer, framesPerSecond, video);
  if (std::system(command.c_str()) != 0) throw RenderError("ffmpeg failed: " + command);
  return video;
}

}  // namespace impulse2d::render
