# Sourced by setup.sh, sanitize.sh and fuzz.sh from the checkout's root: every build of ours goes
# through Debian's ccache, so a rebuild after a checkout, another clone or worktree of the same
# sources, or a CI run on a machine that built them before compiles only what changed. Paths are
# taken relative to the checkout (CCACHE_BASEDIR, and the build folder left out of the hash), so
# clones in other folders share objects; a cold cache costs a few percent over a plain build.
scripts/apt_need.sh ccache
export CCACHE_BASEDIR=$PWD CCACHE_NOHASHDIR=true
ccache_launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
