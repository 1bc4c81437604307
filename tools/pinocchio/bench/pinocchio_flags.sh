# Sourced by compare.sh and compare_suite.sh: where the `pin` wheel keeps
# Pinocchio's headers and libraries (its cmeel prefix), checked, and the g++
# flags every timing program here is built with (-O3, baseline x86-64, no
# -march=native). Sets PREFIX, CXXFLAGS and LDFLAGS.

PREFIX="$(python3 -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')/cmeel.prefix"
for header in pinocchio/config.hpp eigen3/Eigen/Core urdfdom_headers/urdf_model/model.h; do
    if [[ ! -e "$PREFIX/include/$header" ]]; then
        echo "missing $PREFIX/include/$header: pip install pin cmeel-eigen cmeel-urdfdom-headers" >&2
        exit 1
    fi
done

CXXFLAGS=(-std=c++17 -O3 -DNDEBUG -g
    -I"$PREFIX/include" -I"$PREFIX/include/eigen3"
    -I"$PREFIX/include/urdfdom" -I"$PREFIX/include/urdfdom_headers"
    -DPINOCCHIO_WITH_URDFDOM
    -DPINOCCHIO_URDFDOM_HEADERS_MAJOR_VERSION=3
    -DPINOCCHIO_URDFDOM_HEADERS_MINOR_VERSION=0
    -DPINOCCHIO_URDFDOM_HEADERS_PATCH_VERSION=0
    -DBOOST_MPL_LIMIT_LIST_SIZE=30 -DBOOST_MPL_LIMIT_VECTOR_SIZE=30
    -DBOOST_MPL_CFG_NO_PREPROCESSED_HEADERS -DBOOST_FUSION_INVOKE_MAX_ARITY=12)
LDFLAGS=(-L"$PREFIX/lib" -Wl,-rpath,"$PREFIX/lib"
    -lpinocchio_parsers -lpinocchio_default -lurdfdom_model -lconsole_bridge
    -ltinyxml2 -lboost_filesystem)
