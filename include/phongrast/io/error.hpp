// The one exception type of phongrast::io: a problem with a file the user gave
// (missing, unreadable, malformed, invalid values) or could not be written.
// The message always starts with the file name and, where it helps, the line
// ("mesh.obj:12: ...") or the JSON pointer ("scene.json: /camera/eye: ...").
#ifndef PHONGRAST_IO_ERROR_HPP
#define PHONGRAST_IO_ERROR_HPP

#include <stdexcept>
#include <string>

namespace phongrast::io {

class FileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace phongrast::io

#endif  // PHONGRAST_IO_ERROR_HPP
