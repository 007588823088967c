#include "pbrfit/texture/exr.hpp"

#include <climits>
#include <cstring>
#include <stdexcept>

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include "encoding.hpp"

namespace pbrfit::texture {
namespace {

using namespace detail;

// An Imf::OStream into a byte buffer; OpenEXR seeks back to fill in the line offset table.
class MemoryStream : public Imf::OStream {
 public:
  MemoryStream() : Imf::OStream("memory") {}
  void write(const char c[], int n) override {
    if (position_ + std::size_t(n) > bytes_.size()) bytes_.resize(position_ + std::size_t(n));
    std::memcpy(bytes_.data() + position_, c, std::size_t(n));
    position_ += std::size_t(n);
  }
  uint64_t tellp() override { return position_; }
  void seekp(uint64_t pos) override { position_ = pos; }
  Bytes take() { return std::move(bytes_); }

 private:
  Bytes bytes_;
  std::size_t position_ = 0;
};

template <class T>
Bytes write_image(const Texture& t, Imf::PixelType type, std::vector<T> samples) {
  const int width = int(t.width), height = int(t.height), channels = int(t.channels.size());
  Imf::Header header(width, height);
  header.compression() = Imf::ZIP_COMPRESSION;
  header.lineOrder() = Imf::INCREASING_Y;
  for (const auto& [key, value] : text_entries(t)) header.insert("pbrfit:" + key, Imf::StringAttribute(value));
  static const char* const names[] = {"R", "G", "B", "A"};
  Imf::FrameBuffer frame;
  const std::size_t x_stride = sizeof(T) * std::size_t(channels), y_stride = x_stride * std::size_t(width);
  for (int c = 0; c < channels; ++c) {
    const char* name = channels == 1 ? "Y" : names[c];
    header.channels().insert(name, Imf::Channel(type));
    frame.insert(name, Imf::Slice(type, reinterpret_cast<char*>(samples.data() + c), x_stride, y_stride));
  }
  MemoryStream stream;
  {
    Imf::OutputFile file(stream, header);
    file.setFrameBuffer(frame);
    file.writePixels(height);
  }
  return stream.take();
}

}  // namespace

Bytes encode_exr(const Texture& t, Precision precision) {
  check_texture(t, "exr");
  require_one_image(t, "exr");
  if (t.width >= INT_MAX || t.height >= INT_MAX)
    refuse("exr", "holds images below 2^31 - 1 texels a side, not " + std::to_string(t.width) + " x " +
                      std::to_string(t.height));
  try {
    if (precision == Precision::f32) {
      std::vector<float> samples(t.values.size());
      for (std::size_t i = 0; i < samples.size(); ++i) samples[i] = to_float(t.values[i]);
      return write_image(t, Imf::FLOAT, std::move(samples));
    }
    std::vector<Imath::half> samples(t.values.size());
    for (std::size_t i = 0; i < samples.size(); ++i) samples[i].setBits(half_bits(t.values[i]));
    return write_image(t, Imf::HALF, std::move(samples));
  } catch (const std::invalid_argument&) {
    throw;
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("exr: OpenEXR failed: ") + e.what());
  }
}

}  // namespace pbrfit::texture
