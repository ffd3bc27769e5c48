#include <simpson/verify/environment.hpp>

#include "git_commit.hpp"

#include <Eigen/Core>
#include <boost/version.hpp>
#include <gmp.h>
#include <mpfr.h>

namespace simpson::verify {

json build_environment() {
  return json{{"compiler", std::string("g++-compatible ") + __VERSION__},
              {"flags", SIMPSON_CXX_FLAGS},
              {"boost", BOOST_LIB_VERSION},
              {"mpfr", MPFR_VERSION_STRING},
              {"gmp", gmp_version},
              {"eigen", std::to_string(EIGEN_WORLD_VERSION) + "." + std::to_string(EIGEN_MAJOR_VERSION) + "." +
                            std::to_string(EIGEN_MINOR_VERSION)},
              {"git_commit", SIMPSON_GIT_COMMIT}};
}

}  // namespace simpson::verify
