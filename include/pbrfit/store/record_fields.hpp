#pragma once
// One field of a record (compound) table, read whole: its value at every row, in row order, whatever the
// other fields are. Number fields (any integer or float type) come as doubles, text fields (UTF-8) as
// strings; a table with no rows yet gives an empty vector. A missing file or table, a table that is not a
// record table, a missing field and a field of the other kind (a text read as a number, or the reverse)
// are RunErrors naming the table and the field.
#include <string>
#include <vector>

namespace pbrfit::store {

std::vector<double> read_number_field(const std::string& path, const std::string& dataset, const std::string& field);
std::vector<std::string> read_text_field(const std::string& path, const std::string& dataset, const std::string& field);

}  // namespace pbrfit::store
