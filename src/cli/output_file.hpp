#pragma once
// Where a command's output goes: a file written whole or not at all, a
// device or FIFO written through, or standard output.
#include <functional>
#include <initializer_list>
#include <string>
#include <string_view>

namespace bezcam::cli {

/// Writes `data` to `path` without ever destroying what is there:
///  - a regular file (or a new one) atomically: a temporary file beside it,
///    renamed into place only when complete, with the replaced file's mode
///    and owner, so a refused or failed run never leaves a partial or
///    truncated file;
///  - a symbolic link is followed: its target is written, the link stays;
///  - anything else (a serial port for DNC, a FIFO, /dev/null) is written
///    through, every write checked, never replaced by a file;
///  - "-" writes to stdout.
/// A failed write is an IoError naming the path and the cause.
void write_output(const std::string& path, const std::string& data);

/// Receives the output's text in order, piece by piece.
using OutputSink = std::function<void(std::string_view)>;
/// Makes the output: hands its text to the sink as it goes; may throw.
using OutputProducer = std::function<void(const OutputSink&)>;
/// The same, streamed: `produce` writes the text in pieces, never held
/// whole. A regular file is still renamed into place only when `produce`
/// has returned: an exception (a refusal found while writing) leaves no
/// file, or the old one. Standard output and devices receive the pieces
/// as they come.
void write_output(const std::string& path, const OutputProducer& produce);

/// Refuses (InputError naming `option`, before anything is written) an
/// output file whose extension names another format than the one the
/// command writes: `path`'s extension, in any case, must be one of `exts`
/// (".svg") or absent (also standard output "-" and devices). `writes`
/// says what the command writes ("preview writes SVG only").
void require_output_extension(const std::string& path, const std::string& option,
                              std::initializer_list<std::string_view> exts, const std::string& writes);

}  // namespace bezcam::cli
