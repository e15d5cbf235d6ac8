#include "work_queue.hpp"

#include <mpi.h>

#include <cstring>
#include <iostream>
#include <string>
#include <type_traits>
#include <vector>

#include "job.hpp"
#include "render/render_limits.hpp"

namespace rise::mpi {
namespace {

// A rank says it is ready, sends a result or says it failed; rank 0 answers
// with an item or with the word to stop.
enum Tag : int { kReady = 1, kResult, kFailed, kWork, kStop };

// A result as the bytes of one message: the image, each buffer by name, and
// each statistic by name, in order.
class Packer {
 public:
  template <typename Value>
  void put(const Value& value) {
    static_assert(std::is_trivially_copyable_v<Value>);
    putBytes(&value, sizeof value);
  }
  void put(const std::string& text) {
    put(static_cast<int>(text.size()));
    putBytes(text.data(), text.size());
  }
  void put(const Image& image) {
    put(image.width());
    put(image.height());
    putBytes(image.pixels().data(), image.pixels().size() * sizeof(Color));
  }
  const std::vector<char>& bytes() const { return bytes_; }

 private:
  void putBytes(const void* data, std::size_t size) {
    const char* begin = static_cast<const char*>(data);
    bytes_.insert(bytes_.end(), begin, begin + size);
  }
  std::vector<char> bytes_;
};

class Unpacker {
 public:
  explicit Unpacker(const std::vector<char>& bytes) : bytes_(bytes) {}
  template <typename Value>
  Value get() {
    Value value;
    getBytes(&value, sizeof value);
    return value;
  }
  std::string getText() {
    std::string text(static_cast<std::size_t>(get<int>()), '\0');
    getBytes(text.data(), text.size());
    return text;
  }
  Image getImage() {
    const int width = get<int>();
    const int height = get<int>();
    Image image(width, height);
    if (!image.pixels().empty()) getBytes(&image.at(0, 0), image.pixels().size() * sizeof(Color));
    return image;
  }

 private:
  void getBytes(void* data, std::size_t size) {
    std::memcpy(data, bytes_.data() + read_, size);
    read_ += size;
  }
  const std::vector<char>& bytes_;
  std::size_t read_ = 0;
};

std::vector<char> pack(const RenderResult& result) {
  Packer packer;
  packer.put(result.image);
  packer.put(static_cast<int>(result.buffers.size()));
  for (const auto& [name, buffer] : result.buffers) {
    packer.put(name);
    packer.put(buffer);
  }
  packer.put(static_cast<int>(result.stats.entries().size()));
  for (const auto& [name, value] : result.stats.entries()) {
    packer.put(name);
    packer.put(value);
  }
  return packer.bytes();
}

RenderResult unpack(const std::vector<char>& bytes) {
  Unpacker unpacker(bytes);
  RenderResult result;
  result.image = unpacker.getImage();
  for (int buffers = unpacker.get<int>(); buffers > 0; --buffers) {
    std::string name = unpacker.getText();
    result.buffers[name] = unpacker.getImage();
  }
  for (int stats = unpacker.get<int>(); stats > 0; --stats) {
    std::string name = unpacker.getText();
    result.stats.add(std::move(name), unpacker.get<double>());
  }
  return result;
}

RenderResult receiveResult(const MPI_Status& probed) {
  int size = 0;
  MPI_Get_count(&probed, MPI_BYTE, &size);
  std::vector<char> bytes(static_cast<std::size_t>(size));
  MPI_Recv(bytes.data(), size, MPI_BYTE, probed.MPI_SOURCE, kResult, MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  return unpack(bytes);
}

void sendStatus(Tag tag, int status) { MPI_Send(&status, 1, MPI_INT, 0, tag, MPI_COMM_WORLD); }

}  // namespace

int handOut(int ranks, int count, int status,
            const std::function<int(int item, RenderResult result)>& take) {
  std::vector<int> held(static_cast<std::size_t>(ranks), -1);
  int next = 0;
  for (int active = ranks - 1; active > 0;) {
    MPI_Status probed;
    MPI_Probe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &probed);
    const int rank = probed.MPI_SOURCE;
    if (probed.MPI_TAG == kResult) {
      RenderResult result = receiveResult(probed);
      // After a failure nothing more is written.
      if (status == 0) status = take(held[static_cast<std::size_t>(rank)], std::move(result));
    } else {
      int rankStatus = 0;
      MPI_Recv(&rankStatus, 1, MPI_INT, rank, probed.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      if (probed.MPI_TAG == kFailed) {
        if (status == 0) {
          status = rankStatus;
          std::cerr << "rise-mpi: rank " << rank << " failed; the run stops\n";
        }
        --active;
        continue;
      }
    }
    if (status != 0 || next == count) {
      MPI_Send(nullptr, 0, MPI_INT, rank, kStop, MPI_COMM_WORLD);
      --active;
      continue;
    }
    held[static_cast<std::size_t>(rank)] = next;
    MPI_Send(&next, 1, MPI_INT, rank, kWork, MPI_COMM_WORLD);
    ++next;
  }
  return status;
}

int serve(int prepared, const std::function<RenderResult(int item)>& render) {
  if (prepared != 0) {
    sendStatus(kFailed, prepared);
    return prepared;
  }
  sendStatus(kReady, 0);
  for (;;) {
    MPI_Status status;
    int item = 0;
    MPI_Recv(&item, 1, MPI_INT, 0, MPI_ANY_TAG, MPI_COMM_WORLD, &status);
    if (status.MPI_TAG == kStop) return 0;
    int failure = cli::kExitOutputError;
    try {
      const std::vector<char> bytes = pack(render(item));
      MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, 0, kResult, MPI_COMM_WORLD);
      continue;
    } catch (const RenderLimitError& error) {
      std::cerr << "rise-mpi: " << error.what() << "\n";
      failure = cli::kExitBadInput;
    } catch (const std::exception& error) {
      std::cerr << "rise-mpi: " << error.what() << "\n";
    }
    sendStatus(kFailed, failure);
    return failure;
  }
}

}  // namespace rise::mpi
