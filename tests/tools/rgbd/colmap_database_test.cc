#include "tools/rgbd/colmap_database.h"

#include <gtest/gtest.h>
#include <sqlite3.h>

#include <cstring>

#include "io/errors.h"
#include "tests/support/temp_dir.h"

namespace msp {
namespace rgbd {
namespace {

// The columns of COLMAP 3.8's `cameras` and `images` tables that matter here.
void MakeDatabase(const std::string& path) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  const char* sql =
      "CREATE TABLE cameras (camera_id INTEGER PRIMARY KEY, model INTEGER, width INTEGER, "
      "height INTEGER, params BLOB, prior_focal_length INTEGER);"
      "CREATE TABLE images (image_id INTEGER PRIMARY KEY, name TEXT, camera_id INTEGER);"
      "INSERT INTO cameras VALUES (1, 2, 10, 10, x'00', 0);"
      "INSERT INTO images VALUES (2, 'b.png', 1);"
      "INSERT INTO images VALUES (1, 'sub/a.png', 1);";
  ASSERT_EQ(sqlite3_exec(db, sql, nullptr, nullptr, nullptr), SQLITE_OK);
  sqlite3_close(db);
}

TEST(ColmapDatabase, ReadsImageIdsAndSetsTheKnownCamera) {
  const test::TempDir dir;
  const std::string path = dir / "database.db";
  MakeDatabase(path);
  const std::vector<DatabaseImage> images = ReadDatabaseImages(path);
  ASSERT_EQ(images.size(), 2u);
  EXPECT_EQ(images[0].image_id, 1u);
  EXPECT_EQ(images[0].name, "sub/a.png");
  EXPECT_EQ(images[1].camera_id, 1u);

  const double params[4] = {500.25, 501.5, 270.0, 180.5};
  SetPinholeCamera(path, 1, 540, 360, params);
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  sqlite3_stmt* s = nullptr;
  ASSERT_EQ(sqlite3_prepare_v2(db,
                               "SELECT model, width, height, params, prior_focal_length "
                               "FROM cameras WHERE camera_id = 1",
                               -1, &s, nullptr),
            SQLITE_OK);
  ASSERT_EQ(sqlite3_step(s), SQLITE_ROW);
  EXPECT_EQ(sqlite3_column_int(s, 0), 1);  // PINHOLE
  EXPECT_EQ(sqlite3_column_int(s, 1), 540);
  EXPECT_EQ(sqlite3_column_int(s, 2), 360);
  ASSERT_EQ(sqlite3_column_bytes(s, 3), static_cast<int>(sizeof(params)));
  EXPECT_EQ(std::memcmp(sqlite3_column_blob(s, 3), params, sizeof(params)), 0);
  EXPECT_EQ(sqlite3_column_int(s, 4), 1);
  sqlite3_finalize(s);
  sqlite3_close(db);
}

TEST(ColmapDatabase, MissingCameraOrDatabaseIsAnInputError) {
  const test::TempDir dir;
  MakeDatabase(dir / "database.db");
  const double params[4] = {1, 1, 0, 0};
  EXPECT_THROW(SetPinholeCamera(dir / "database.db", 7, 10, 10, params), InputError);
  EXPECT_THROW(ReadDatabaseImages(dir / "none.db"), InputError);
}

}  // namespace
}  // namespace rgbd
}  // namespace msp
