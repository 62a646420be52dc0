#include "core/ExitOnError.hpp"

#include <gtest/gtest.h>

TEST(ExitOnError, FilesystemErrorsNameThePathAndTheCause) {
    // Was "internal error: filesystem error: ..." (exit 3) on c09449c.
    const std::filesystem::filesystem_error error("cannot create directories", "/case/postProcessing/line/0",
                                                  std::make_error_code(std::errc::read_only_file_system));
    EXPECT_EQ(sph::describeFilesystemError(error), "cannot create directories '/case/postProcessing/line/0': Read-only file system");
    const std::filesystem::filesystem_error rename("cannot rename", "/a", "/b", std::make_error_code(std::errc::permission_denied));
    EXPECT_EQ(sph::describeFilesystemError(rename), "cannot rename '/a' to '/b': Permission denied");
    EXPECT_EQ(sph::exitCodeOf([&] { throw error; }), 1);
    EXPECT_EQ(sph::exitCodeOf([] { throw sph::FatalError("error: bad input"); }), 1);
    EXPECT_EQ(sph::exitCodeOf([] { throw std::logic_error("a bug"); }), 3);
    EXPECT_EQ(sph::exitCodeOf([] {}), 0);
}
