// ctest-labels: io
// HDF5 particle output (io/hdf5_particles.h, io/hdf5_file.h) read back through the HDF5 C API
// value for value, with its units and compression; the XDMF index (io/xdmf_particles.h) points
// at datasets that exist with the shapes it declares; a writer killed after a frame leaves that
// frame readable in particles.h5.partial and no particles.h5 that would look complete.
#include "slides/io/atomic_file.h"
#include "slides/io/hdf5_particles.h"

#include <gtest/gtest.h>

#include <vtkNew.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

namespace slides {
namespace {

namespace fs = std::filesystem;

class Hdf5Output : public testing::Test {
protected:
    void SetUp() override {
        const auto* test = testing::UnitTest::GetInstance()->current_test_info();
        directory_ = fs::temp_directory_path() /
                     ("slides_hdf5_output_" + std::to_string(::getpid()) + "_" + test->name());
        fs::remove_all(directory_);
        fs::create_directories(directory_);
    }
    void TearDown() override { fs::remove_all(directory_); }
    fs::path directory_;
};

/// Three particles with values that survive only an exact write (non-representable decimals,
/// a huge id, a negative component).
struct KnownFrame {
    std::vector<std::uint64_t> id{7, 0, 18446744073709551557ULL};
    std::vector<Vec3> position{{0.1, -0.2, 0.3}, {1e-9, 2.5, -7.75}, {0, 0, 1.0 / 3}};
    std::vector<Vec3> velocity{{3, 4, 0}, {-1.5, 0.25, 2}, {1e3, -1e-3, 0.1}};
    std::vector<double> radius{1e-6, 2.5e-5, 0.1 / 3};
    std::vector<std::int32_t> state{0, 1, 0};

    ParticleFrame frame() const { return {id, position, velocity, radius, state}; }
};

/// Reading side, through the plain C API, so the test does not share code with the writer.
class Reader {
public:
    explicit Reader(const fs::path& file)
        : file_(H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT)) {}
    ~Reader() {
        if (file_ >= 0) H5Fclose(file_);
    }
    bool open() const { return file_ >= 0; }
    bool exists(const std::string& path) const {
        return H5Lexists(file_, path.c_str(), H5P_DEFAULT) > 0;
    }

    /// Dimensions of a dataset.
    std::vector<hsize_t> shape(const std::string& path) const {
        const hid_t dataset = H5Dopen2(file_, path.c_str(), H5P_DEFAULT);
        const hid_t space = H5Dget_space(dataset);
        std::vector<hsize_t> dims(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)));
        H5Sget_simple_extent_dims(space, dims.data(), nullptr);
        H5Sclose(space);
        H5Dclose(dataset);
        return dims;
    }

    template <typename Value> std::vector<Value> values(const std::string& path, hid_t type) const {
        std::size_t count = 1;
        for (hsize_t n : shape(path)) count *= n;
        std::vector<Value> out(count);
        const hid_t dataset = H5Dopen2(file_, path.c_str(), H5P_DEFAULT);
        if (count > 0) H5Dread(dataset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data());
        H5Dclose(dataset);
        return out;
    }

    std::string text(const std::string& object, const std::string& name) const {
        const hid_t attribute =
            H5Aopen_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
        const hid_t type = H5Aget_type(attribute);
        std::string out(H5Tget_size(type), '\0');
        H5Aread(attribute, type, out.data());
        H5Tclose(type);
        H5Aclose(attribute);
        return out.substr(0, out.find('\0'));
    }

    template <typename Value>
    Value number(const std::string& object, const std::string& name, hid_t type) const {
        const hid_t attribute =
            H5Aopen_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
        Value out{};
        H5Aread(attribute, type, &out);
        H5Aclose(attribute);
        return out;
    }

    /// The filters of a dataset's pipeline, e.g. {H5Z_FILTER_SHUFFLE, H5Z_FILTER_DEFLATE}.
    std::vector<H5Z_filter_t> filters(const std::string& path) const {
        const hid_t dataset = H5Dopen2(file_, path.c_str(), H5P_DEFAULT);
        const hid_t creation = H5Dget_create_plist(dataset);
        std::vector<H5Z_filter_t> out;
        for (int n = 0; n < H5Pget_nfilters(creation); ++n) {
            unsigned flags = 0;
            std::size_t elements = 0;
            out.push_back(H5Pget_filter2(creation, static_cast<unsigned>(n), &flags, &elements,
                                         nullptr, 0, nullptr, nullptr));
        }
        H5Pclose(creation);
        H5Dclose(dataset);
        return out;
    }

private:
    hid_t file_;
};

TEST_F(Hdf5Output, FramesAndArrivalsReadBackExactlyWithUnits) {
    const KnownFrame known;
    {
        ParticlesHdf5 output(directory_, "/cases/known");
        output.writeFrame(0.0, ParticleFrame{});
        output.writeFrame(0.125, known.frame());
        const std::vector<Arrival> arrivals{
            {7, 0, 0.0625, {0.06, 1e-3, -2e-3}, {24.5, 0.1, -0.2}, 4e-5},
            {9, 1, 0.1, {0.06, 0, 0}, {20, 0, 0}, 8e-5}};
        output.finish(arrivals);
    }
    EXPECT_FALSE(fs::exists(directory_ / "particles.h5.partial"));
    const Reader file(directory_ / "particles.h5");
    ASSERT_TRUE(file.open());
    EXPECT_EQ(file.text("/", "software"), "SLIDES-track");
    EXPECT_EQ(file.text("/", "version"), SLIDES_VERSION);
    EXPECT_EQ(file.text("/", "case"), "/cases/known");
    EXPECT_EQ(file.number<std::int64_t>("/", "frames", H5T_NATIVE_INT64), 2);

    EXPECT_EQ(file.number<double>("/frames/000000", "time", H5T_NATIVE_DOUBLE), 0.0);
    EXPECT_EQ(file.shape("/frames/000000/position"), (std::vector<hsize_t>{0, 3}));
    EXPECT_EQ(file.shape("/frames/000000/id"), (std::vector<hsize_t>{0}));

    const std::string frame = "/frames/000001/";
    EXPECT_EQ(file.number<double>("/frames/000001", "time", H5T_NATIVE_DOUBLE), 0.125);
    ASSERT_EQ(file.shape(frame + "position"), (std::vector<hsize_t>{3, 3}));
    const auto position = file.values<double>(frame + "position", H5T_NATIVE_DOUBLE);
    const auto velocity = file.values<double>(frame + "velocity", H5T_NATIVE_DOUBLE);
    const auto id = file.values<std::uint64_t>(frame + "id", H5T_NATIVE_UINT64);
    const auto diameter = file.values<double>(frame + "diameter", H5T_NATIVE_DOUBLE);
    const auto speed = file.values<double>(frame + "speed", H5T_NATIVE_DOUBLE);
    const auto state = file.values<std::int32_t>(frame + "state", H5T_NATIVE_INT32);
    for (std::size_t i = 0; i < 3; ++i) {
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(position[3 * i + c], known.position[i][c]);
            EXPECT_EQ(velocity[3 * i + c], known.velocity[i][c]);
        }
        EXPECT_EQ(id[i], known.id[i]);
        EXPECT_EQ(diameter[i], 2 * known.radius[i]);
        EXPECT_EQ(speed[i], known.velocity[i].norm());
        EXPECT_EQ(state[i], known.state[i]);
    }
    EXPECT_EQ(speed[0], 5.0);
    for (const auto& [name, units] :
         std::vector<std::pair<std::string, std::string>>{{"position", "m"},
                                                          {"velocity", "m/s"},
                                                          {"diameter", "m"},
                                                          {"speed", "m/s"},
                                                          {"id", "1"},
                                                          {"state", "1"}}) {
        EXPECT_EQ(file.text(frame + name, "units"), units) << name;
        EXPECT_EQ(file.filters(frame + name),
                  (std::vector<H5Z_filter_t>{H5Z_FILTER_SHUFFLE, H5Z_FILTER_DEFLATE}))
            << name;
    }

    EXPECT_EQ(file.values<std::uint64_t>("/arrivals/id", H5T_NATIVE_UINT64),
              (std::vector<std::uint64_t>{7, 9}));
    EXPECT_EQ(file.values<std::int32_t>("/arrivals/surface", H5T_NATIVE_INT32),
              (std::vector<std::int32_t>{0, 1}));
    EXPECT_EQ(file.values<double>("/arrivals/time", H5T_NATIVE_DOUBLE),
              (std::vector<double>{0.0625, 0.1}));
    EXPECT_EQ(file.values<double>("/arrivals/diameter", H5T_NATIVE_DOUBLE),
              (std::vector<double>{8e-5, 1.6e-4}));
    EXPECT_EQ(file.values<double>("/arrivals/velocity", H5T_NATIVE_DOUBLE),
              (std::vector<double>{24.5, 0.1, -0.2, 20, 0, 0}));
    EXPECT_EQ(file.text("/arrivals/time", "units"), "s");
}

TEST_F(Hdf5Output, FrameCarriesPositionAndExactlyTheSelectedFields) {
    const KnownFrame known;
    ParticleFrame frame = known.frame();
    frame.fields = ParticleFieldSet().add(ParticleField::velocity).add(ParticleField::state);
    {
        ParticlesHdf5 output(directory_, "selected");
        output.writeFrame(1.0, frame);
        output.finish({});
    }
    const Reader file(directory_ / "particles.h5");
    for (const char* name : {"position", "velocity", "state"})
        EXPECT_TRUE(file.exists(std::string("/frames/000000/") + name)) << name;
    for (const char* name : {"id", "diameter", "speed"})
        EXPECT_FALSE(file.exists(std::string("/frames/000000/") + name)) << name;
    EXPECT_EQ(file.shape("/arrivals/position"), (std::vector<hsize_t>{0, 3}));
}

TEST_F(Hdf5Output, SpinIsADatasetInRadiansPerSecondOnlyWhereTracked) {
    const KnownFrame known;
    const std::vector<Vec3> spin{{1e4, -2, 0}, {0, 0, 1.0 / 7}, {-5e-3, 3e5, 1}};
    ParticleFrame spinning = known.frame();
    spinning.angularVelocity = spin;
    {
        ParticlesHdf5 output(directory_, "spin");
        output.writeFrame(0.5, spinning);
        output.writeFrame(1.0, known.frame());
        output.finish({});
    }
    const Reader file(directory_ / "particles.h5");
    ASSERT_TRUE(file.exists("/frames/000000/angularVelocity"));
    EXPECT_EQ(file.shape("/frames/000000/angularVelocity"), (std::vector<hsize_t>{3, 3}));
    EXPECT_EQ(file.text("/frames/000000/angularVelocity", "units"), "rad/s");
    const auto values = file.values<double>("/frames/000000/angularVelocity", H5T_NATIVE_DOUBLE);
    for (std::size_t i = 0; i < 3; ++i)
        for (int c = 0; c < 3; ++c) EXPECT_EQ(values[3 * i + c], spin[i][c]);
    EXPECT_FALSE(file.exists("/frames/000001/angularVelocity"));
    // The index names it (a Vector) in the first frame only.
    const std::string index = [&] {
        std::ifstream in(directory_ / "particles.xmf");
        return std::string(std::istreambuf_iterator<char>(in), {});
    }();
    EXPECT_NE(index.find("<Attribute Name=\"angularVelocity\" AttributeType=\"Vector\""),
              std::string::npos);
    EXPECT_EQ(index.find("000001/angularVelocity"), std::string::npos);
}

/// Each DataItem of an XDMF document: its "file:/path" reference and declared dimensions.
std::vector<std::pair<std::string, std::string>> dataItems(vtkXMLDataElement* element) {
    std::vector<std::pair<std::string, std::string>> items;
    if (std::string(element->GetName()) == "DataItem")
        items.emplace_back(element->GetCharacterData(), element->GetAttribute("Dimensions"));
    for (int n = 0; n < element->GetNumberOfNestedElements(); ++n) {
        auto nested = dataItems(element->GetNestedElement(n));
        items.insert(items.end(), nested.begin(), nested.end());
    }
    return items;
}

TEST_F(Hdf5Output, XdmfIndexPointsAtEveryNonEmptyFrameWithMatchingShapes) {
    const KnownFrame known;
    {
        ParticlesHdf5 output(directory_, "indexed");
        output.writeFrame(0.0, ParticleFrame{}); // no particles yet: not in the index
        output.writeFrame(0.5, known.frame());
        output.writeFrame(1.0, known.frame());
        output.finish({});
    }
    vtkNew<vtkXMLDataParser> parser;
    parser->SetFileName((directory_ / "particles.xmf").c_str());
    ASSERT_EQ(parser->Parse(), 1) << "particles.xmf is not valid XML";
    vtkXMLDataElement* root = parser->GetRootElement();
    ASSERT_STREQ(root->GetName(), "Xdmf");
    vtkXMLDataElement* series = root->GetNestedElement(0)->GetNestedElement(0);
    ASSERT_STREQ(series->GetAttribute("CollectionType"), "Temporal");
    ASSERT_EQ(series->GetNumberOfNestedElements(), 2);
    std::vector<double> times;
    for (int n = 0; n < 2; ++n)
        times.push_back(std::stod(
            series->GetNestedElement(n)->FindNestedElementWithName("Time")->GetAttribute("Value")));
    EXPECT_EQ(times, (std::vector<double>{0.5, 1.0}));

    const Reader file(directory_ / "particles.h5");
    const auto items = dataItems(root);
    EXPECT_EQ(items.size(), 2u * 6u) << "position and the five fields, per frame";
    for (const auto& [reference, dimensions] : items) {
        const auto colon = reference.find(':');
        ASSERT_NE(colon, std::string::npos) << reference;
        EXPECT_EQ(reference.substr(0, colon), "particles.h5");
        const std::string path = reference.substr(colon + 1);
        ASSERT_TRUE(file.exists(path)) << path;
        std::ostringstream shape;
        for (std::size_t d = 0; const hsize_t n : file.shape(path)) shape << (d++ ? " " : "") << n;
        EXPECT_EQ(shape.str(), dimensions) << path;
    }
}

TEST_F(Hdf5Output, KilledWriterLeavesFlushedFramesInThePartialFileOnly) {
    // A child process writes one frame and dies without closing anything (as under kill -9).
    const KnownFrame known;
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        ParticlesHdf5 output(directory_, "killed");
        output.writeFrame(0.25, known.frame());
        ::_exit(9);
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 9);
    EXPECT_FALSE(fs::exists(directory_ / "particles.h5")) << "an unfinished run looks complete";
    EXPECT_FALSE(fs::exists(directory_ / "particles.xmf"));
    const Reader file(directory_ / "particles.h5.partial");
    ASSERT_TRUE(file.open()) << "the flushed frame must be readable";
    EXPECT_EQ(file.number<double>("/frames/000000", "time", H5T_NATIVE_DOUBLE), 0.25);
    EXPECT_EQ(file.values<std::uint64_t>("/frames/000000/id", H5T_NATIVE_UINT64), known.id);
}

TEST_F(Hdf5Output, UnwritableDirectoryGivesOutputErrorNamingTheFile) {
    try {
        ParticlesHdf5 output(directory_ / "missing" / "folder", "nowhere");
        FAIL() << "no error";
    } catch (const OutputError& error) {
        EXPECT_NE(std::string(error.what()).find("missing/folder/particles.h5.partial"),
                  std::string::npos)
            << error.what();
    }
}

} // namespace
} // namespace slides
