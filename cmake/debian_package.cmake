# The Debian package: `cpack -G DEB` in a build folder makes
# msp-stereo_<version>_<arch>.deb. Everything installs under
# /usr/lib/msp-stereo (bin/ holds msp_stereo, the tools and the `colmap`
# dispatcher), never in /usr/bin, so Debian's own colmap is not shadowed; a
# user puts /usr/lib/msp-stereo/bin first on PATH to get `colmap msp_stereo`.
# `cmake --install` keeps its usual <prefix>/bin.
set(CPACK_PACKAGE_NAME msp-stereo)
set(CPACK_PACKAGE_CONTACT "msp-stereo maintainers <msp-stereo@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "MSP-MVS dense stereo for COLMAP (colmap msp_stereo, a CPU patch_match_stereo)")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr/lib/msp-stereo)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
# The runtime libraries (OpenCV, Boost.Program_options, libstdc++, ...) come
# from dpkg-shlibdeps, so the list follows what the binaries really link; the
# dispatcher needs the real COLMAP, which no binary links.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "colmap")
include(CPack)
