# shellcheck shell=bash
# Helpers of the viewer tests (bash, set -euo pipefail); the CLI tests' helpers first.
# shellcheck source=../cli/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/../cli/common.sh"
VIEWER_TESTS="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"

# Skip (exit 77) when there is no headless Chromium to open the pages in.
require_chromium() {
  command -v chromium >/dev/null || command -v chromium-browser >/dev/null || {
    echo "SKIP: no chromium (scripts/setup.sh --for-tests, which scripts/test.sh runs, installs it)"
    exit 77
  }
}
