// `phongrast batch --status MANIFEST -o OUTDIR`: which jobs are done (every
// image exists; images are renamed into place whole, so existing means
// complete), which failed (their latest log record, over every shard's log,
// says failed or timeout) and which are missing (neither: not run yet, or a
// shard was killed while on them).
#ifndef PHONGRAST_APPS_BATCH_STATUS_HPP
#define PHONGRAST_APPS_BATCH_STATUS_HPP

#include <string>

#include "batch_manifest.hpp"

namespace phongrast::cli {

/// Prints the summary on stdout. Returns 0 when every job is done, else 1.
int print_status(const Manifest& manifest, const std::string& output_folder);

}  // namespace phongrast::cli

#endif  // PHONGRAST_APPS_BATCH_STATUS_HPP
