// msp_convert_masks: SAM-style binary masks -> label layers of the
// segmentation prior. See mask_conversion.h and docs/segmentation_masks.md.
#include <exception>
#include <iostream>
#include <string>

#include "io/mask_conversion.h"
#include "options/option_parser.h"
#include "options/tool_command_line.h"

namespace {

constexpr char kUsage[] =
    "Usage: msp_convert_masks --input_path <sam_masks> --output_path <workspace>/masks";

constexpr char kSummary[] =
    "Turns per-image, per-level folders of binary masks, as SAM-family automatic mask\n"
    "generators write them, into the label layers msp_stereo reads:\n"
    "\n"
    "  input:  <input_path>/<image_name>/<level>/<id>.png   one 0/255 PNG per mask\n"
    "          <input_path>/<image_name>/<level>/metadata.csv  optional, columns id,area,...\n"
    "  output: <output_path>/<image_name>.<level>.png  single-channel 16-bit region ids\n"
    "\n"
    "<image_name> is the name in the sparse model, sub-folders included (e.g. sub/a.jpg);\n"
    "<level> is 0, 1, 2, ... from the coarsest granularity to the finest, without gaps.\n"
    "Within a level, larger masks are painted first and smaller ones over them (the finer\n"
    "region wins where masks overlap); areas come from metadata.csv when it lists them,\n"
    "else from the masks' pixel counts. Pixels under no mask get 0 (unlabelled).\n"
    "Masks must have the size of the undistorted images (<workspace>/images).";

}  // namespace

int main(int argc, char** argv) {
  std::string input_path, output_path;
  msp::ToolCommandLine command_line(kUsage, kSummary);
  command_line.AddRequired("input_path", &input_path,
                           "Folder of SAM-style masks, <image_name>/<level>/<id>.png.");
  command_line.AddRequired("output_path", &output_path,
                           "Folder the label layers are written to, usually <workspace>/masks.");
  try {
    if (command_line.Parse(argc, argv) == msp::ParseStatus::kHelp) {
      std::cout << command_line.Usage();
      return 0;
    }
    if (input_path.empty() || output_path.empty()) {
      throw msp::OptionError("--input_path and --output_path must not be empty");
    }
    const int images = msp::ConvertMasks(input_path, output_path, &std::cout);
    std::cout << "Converted the masks of " << images << " images into " << output_path << "\n";
  } catch (const std::exception& e) {
    std::cout.flush();
    std::cerr << "ERROR: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}
