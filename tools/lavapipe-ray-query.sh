#!/usr/bin/env bash
# Mesa 25's lavapipe, which has ray queries (VK_KHR_ray_query; Debian 12's
# own Mesa 22 has none), for the direct pass's hardware shadow rays
# (`ShadowRays::RayQuery`) on a machine without a GPU. Fetches
# `mesa-vulkan-drivers` from Debian's bookworm-backports into
# target/lavapipe-rq/ without installing it (no root needed; every other
# test keeps the system's driver) and prints the ICD file to point the
# Vulkan loader at:
#
#   VK_ICD_FILENAMES=$(bash tools/lavapipe-ray-query.sh) SLC_REQUIRE_RAY_QUERY=1 \
#       cargo test --workspace --test direct_shadows -- ray_quer
#
# Needs apt-get and dpkg-deb (Debian or Ubuntu) and the Debian mirror.
set -euo pipefail
cd "$(dirname "$0")/.."
dir="$PWD/target/lavapipe-rq"
icd="$dir/lvp_icd.json"
if [ ! -s "$icd" ]; then
    rm -rf "$dir"
    mkdir -p "$dir/lists/partial" "$dir/cache/archives/partial" "$dir/debs"
    echo "deb http://deb.debian.org/debian bookworm-backports main" >"$dir/sources.list"
    apt=(-qq -o Dir::Etc::sourcelist="$dir/sources.list" -o Dir::Etc::sourceparts=-
        -o Dir::State::Lists="$dir/lists" -o Dir::Cache="$dir/cache" -o Debug::NoLocking=1 -o APT::Sandbox::User="$(id -un)")
    apt-get "${apt[@]}" update >&2
    (cd "$dir/debs" && apt-get "${apt[@]}" download mesa-vulkan-drivers/bookworm-backports >&2)
    dpkg-deb -x "$dir"/debs/mesa-vulkan-drivers_*.deb "$dir/root"
    lib=$(find "$dir/root" -name libvulkan_lvp.so | head -n 1)
    [ -n "$lib" ] || { echo "no libvulkan_lvp.so in $(ls "$dir"/debs)" >&2; exit 1; }
    printf '{"file_format_version": "1.0.0", "ICD": {"library_path": "%s", "api_version": "1.3.0"}}\n' \
        "$lib" >"$icd"
    echo "lavapipe with ray queries: $(ls "$dir"/debs)" >&2
fi
echo "$icd"
