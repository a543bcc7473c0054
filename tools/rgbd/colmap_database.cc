#include "tools/rgbd/colmap_database.h"

#include <sqlite3.h>

#include "io/errors.h"
#include "io/sparse_model.h"

namespace msp {
namespace rgbd {
namespace {

constexpr int kPinholeParams = 4;

// An open database, closed on every way out.
class Database {
 public:
  explicit Database(const std::string& path) : path_(path) {
    if (sqlite3_open_v2(path.c_str(), &db_, SQLITE_OPEN_READWRITE, nullptr) != SQLITE_OK) {
      const std::string reason = db_ != nullptr ? sqlite3_errmsg(db_) : "out of memory";
      sqlite3_close(db_);
      throw InputError("cannot open COLMAP database " + path + ": " + reason);
    }
  }
  ~Database() { sqlite3_close(db_); }
  Database(const Database&) = delete;
  Database& operator=(const Database&) = delete;

  sqlite3_stmt* Prepare(const char* sql) {
    sqlite3_stmt* statement = nullptr;
    if (sqlite3_prepare_v2(db_, sql, -1, &statement, nullptr) != SQLITE_OK) Fail("prepare");
    return statement;
  }
  [[noreturn]] void Fail(const char* what) {
    throw InputError("COLMAP database " + path_ + ": " + what + " failed: " + sqlite3_errmsg(db_));
  }
  int Changes() { return sqlite3_changes(db_); }

 private:
  std::string path_;
  sqlite3* db_ = nullptr;
};

// A prepared statement, finalised on every way out.
class Statement {
 public:
  Statement(Database* db, const char* sql) : statement_(db->Prepare(sql)) {}
  ~Statement() { sqlite3_finalize(statement_); }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;
  sqlite3_stmt* get() { return statement_; }

 private:
  sqlite3_stmt* statement_;
};

}  // namespace

std::vector<DatabaseImage> ReadDatabaseImages(const std::string& database_path) {
  Database db(database_path);
  Statement query(&db, "SELECT image_id, camera_id, name FROM images ORDER BY image_id");
  std::vector<DatabaseImage> images;
  int rc = SQLITE_ROW;
  while ((rc = sqlite3_step(query.get())) == SQLITE_ROW) {
    DatabaseImage image;
    image.image_id = static_cast<uint32_t>(sqlite3_column_int64(query.get(), 0));
    image.camera_id = static_cast<uint32_t>(sqlite3_column_int64(query.get(), 1));
    const unsigned char* name = sqlite3_column_text(query.get(), 2);
    image.name = name != nullptr ? reinterpret_cast<const char*>(name) : "";
    images.push_back(image);
  }
  if (rc != SQLITE_DONE) db.Fail("reading the images");
  return images;
}

void SetPinholeCamera(const std::string& database_path, uint32_t camera_id, int width, int height,
                      const double params[4]) {
  Database db(database_path);
  Statement update(&db,
                   "UPDATE cameras SET model = ?, width = ?, height = ?, params = ?, "
                   "prior_focal_length = 1 WHERE camera_id = ?");
  sqlite3_stmt* s = update.get();
  // COLMAP stores the parameters as the raw little-endian doubles.
  if (sqlite3_bind_int(s, 1, kPinhole) != SQLITE_OK ||
      sqlite3_bind_int64(s, 2, width) != SQLITE_OK ||
      sqlite3_bind_int64(s, 3, height) != SQLITE_OK ||
      sqlite3_bind_blob(s, 4, params, kPinholeParams * sizeof(double), SQLITE_TRANSIENT) !=
          SQLITE_OK ||
      sqlite3_bind_int64(s, 5, camera_id) != SQLITE_OK) {
    db.Fail("binding the camera");
  }
  if (sqlite3_step(s) != SQLITE_DONE) db.Fail("updating the camera");
  if (db.Changes() != 1) {
    throw InputError("COLMAP database " + database_path + ": no camera " +
                     std::to_string(camera_id));
  }
}

}  // namespace rgbd
}  // namespace msp
