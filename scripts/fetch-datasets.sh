#!/usr/bin/env bash
# Fetches the larger CGAL demo meshes (too big to keep in git) into datasets/cgal/.
#
# The meshes ship inside Debian's libcgal-demo package (usr/share/doc/libcgal-dev/data.tar.gz,
# folder data/meshes/). We take the package with `apt-get download`, which needs no root,
# and unpack only the meshes listed below. Running it again skips meshes already present.
#
#   scripts/fetch-datasets.sh              # into <repo>/datasets/cgal
#   scripts/fetch-datasets.sh --all        # every mesh of the package (139) into <repo>/datasets/cgal-all
#   CONESCOPE_CGAL_DEB=/path/to/libcgal-demo_*.deb scripts/fetch-datasets.sh   # offline
#
# Exit status is non-zero, with a message on stderr, if anything could not be fetched.
set -euo pipefail

# The larger closed scans and CAD models in libcgal-demo 5.5 (file: vertices / triangles).
MESHES=(
  armadillo.off          # 26002 / 52000
  bunny00.off            # 37706 / 75408   Stanford bunny
  refined_elephant.off   # 44460 / 88928
  ChineseDragon-10kv.off # 10000 / 19994
  diplodocus.off         # 23982 / 47960
  man.off                # 17495 / 34986
  camel.off              #  9770 / 19536
  mannequin-devil.off    # 12977 / 25888
  fandisk_large.off      # 15843 / 31682   CAD part with sharp edges
)

fail() {
  echo "fetch-datasets: error: $*" >&2
  exit 1
}

repository_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
target_dir="${repository_root}/datasets/cgal"
all=0
if [[ "${1:-}" == "--all" ]]; then
  all=1
  target_dir="${repository_root}/datasets/cgal-all"
elif [[ $# -gt 0 ]]; then
  fail "unknown argument '$1' (expected --all or nothing)"
fi
mkdir -p "${target_dir}" || fail "cannot create ${target_dir}"

missing=()
for mesh in "${MESHES[@]}"; do
  [[ -s "${target_dir}/${mesh}" ]] || missing+=("${mesh}")
done
# --all: done once the folder holds the package's meshes (written last, as a marker).
if [[ $all -eq 1 && -f "${target_dir}/.complete" ]]; then
  echo "fetch-datasets: every mesh already present in ${target_dir}"
  exit 0
fi
if [[ $all -eq 0 && ${#missing[@]} -eq 0 ]]; then
  echo "fetch-datasets: all ${#MESHES[@]} meshes already present in ${target_dir}"
  exit 0
fi

for tool in dpkg-deb tar; do
  command -v "${tool}" >/dev/null || fail "'${tool}' is not installed"
done

work_dir="$(mktemp -d)"
trap 'rm -rf "${work_dir}"' EXIT

download_package() {
  # apt-get download writes into the current directory; a failure usually means stale lists.
  (cd "${work_dir}" && apt-get download libcgal-demo) && return 0
  echo "fetch-datasets: download failed, running apt-get update and retrying" >&2
  if [[ $(id -u) -eq 0 ]]; then
    apt-get update >/dev/null || return 1
  else
    sudo -n apt-get update >/dev/null || return 1
  fi
  (cd "${work_dir}" && apt-get download libcgal-demo)
}

if [[ -n "${CONESCOPE_CGAL_DEB:-}" ]]; then
  [[ -f "${CONESCOPE_CGAL_DEB}" ]] || fail "CONESCOPE_CGAL_DEB=${CONESCOPE_CGAL_DEB} is not a file"
  package="${CONESCOPE_CGAL_DEB}"
else
  command -v apt-get >/dev/null || fail "apt-get not found (Debian/Ubuntu only); set CONESCOPE_CGAL_DEB to a downloaded libcgal-demo .deb"
  download_package || fail "could not download libcgal-demo with apt-get (network or apt sources?)"
  package="$(ls "${work_dir}"/libcgal-demo_*.deb 2>/dev/null | head -n 1)"
  [[ -n "${package}" ]] || fail "apt-get download left no libcgal-demo .deb in ${work_dir}"
fi

dpkg-deb -x "${package}" "${work_dir}/package" || fail "cannot unpack ${package}"
data_archive="${work_dir}/package/usr/share/doc/libcgal-dev/data.tar.gz"
[[ -f "${data_archive}" ]] || fail "${package} has no usr/share/doc/libcgal-dev/data.tar.gz"

if [[ $all -eq 1 ]]; then
  tar -xzf "${data_archive}" -C "${work_dir}" data/meshes || fail "data.tar.gz has no data/meshes"
  count=0
  for source_file in "${work_dir}"/data/meshes/*; do
    [[ -f "${source_file}" ]] || continue
    cp "${source_file}" "${target_dir}/"
    count=$((count + 1))
  done
  touch "${target_dir}/.complete"
  echo "fetch-datasets: ${count} files into ${target_dir}"
  exit 0
fi

members=()
for mesh in "${missing[@]}"; do members+=("data/meshes/${mesh}"); done
tar -xzf "${data_archive}" -C "${work_dir}" "${members[@]}" ||
  fail "data.tar.gz lacks some of: ${missing[*]}"

for mesh in "${missing[@]}"; do
  source_file="${work_dir}/data/meshes/${mesh}"
  [[ -s "${source_file}" ]] || fail "${mesh} is empty in the package"
  cp "${source_file}" "${target_dir}/${mesh}.partial"
  mv "${target_dir}/${mesh}.partial" "${target_dir}/${mesh}"
  # Second non-comment line of an OFF file: vertex, face and edge counts.
  counts="$(grep -v '^[[:space:]]*\(#\|$\)' "${target_dir}/${mesh}" | sed -n 2p)"
  printf 'fetch-datasets: fetched %-24s %8s bytes  (vertices faces edges: %s)\n' \
    "${mesh}" "$(stat -c %s "${target_dir}/${mesh}")" "${counts}"
done
echo "fetch-datasets: ${#missing[@]} fetched, $((${#MESHES[@]} - ${#missing[@]})) already present, in ${target_dir}"
