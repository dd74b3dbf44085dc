// ctest-labels: foundation io
// VTK output for ParaView (io/vtk_particles.h, io/pvd_series.h, io/vtk_carrier_grid.h) read back
// with VTK's own XML readers, value for value; and atomic writing (io/atomic_file.h): a failed
// write leaves the previous file intact and no temporary behind.
#include "slides/io/atomic_file.h"
#include "slides/io/pvd_series.h"
#include "slides/io/vtk_carrier_grid.h"
#include "slides/io/vtk_particles.h"

#include "slides/core/particle_cloud.h"

#include <gtest/gtest.h>

#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLPolyDataReader.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

namespace slides {
namespace {

namespace fs = std::filesystem;

/// Each test writes into a fresh directory of its own, removed afterwards.
class VtkOutput : public testing::Test {
protected:
    void SetUp() override {
        const auto* test = testing::UnitTest::GetInstance()->current_test_info();
        directory_ = fs::temp_directory_path() /
                     ("slides_vtk_output_" + std::to_string(::getpid()) + "_" + test->name());
        fs::remove_all(directory_);
        fs::create_directories(directory_);
    }
    void TearDown() override {
        std::error_code ignored;
        fs::permissions(directory_, fs::perms::owner_all, fs::perm_options::add, ignored);
        fs::remove_all(directory_, ignored);
    }

    /// The names of the files in the test's directory, sorted.
    std::vector<std::string> filesPresent() const {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(directory_))
            names.push_back(entry.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }

    fs::path directory_;
};

std::string contents(const fs::path& file) {
    std::ifstream stream(file, std::ios::binary);
    std::ostringstream text;
    text << stream.rdbuf();
    return text.str();
}

/// Fails the current test on every error a VTK reader reports.
void failOnVtkErrors(vtkObject* reader) {
    vtkNew<vtkCallbackCommand> onError;
    onError->SetCallback([](vtkObject*, unsigned long, void*, void* message) {
        ADD_FAILURE() << "VTK reader error: " << static_cast<const char*>(message);
    });
    reader->AddObserver(vtkCommand::ErrorEvent, onError);
}

vtkSmartPointer<vtkPolyData> readVtp(const fs::path& file) {
    vtkNew<vtkXMLPolyDataReader> reader;
    failOnVtkErrors(reader);
    reader->SetFileName(file.c_str());
    reader->Update();
    return reader->GetOutput();
}

vtkSmartPointer<vtkImageData> readVti(const fs::path& file) {
    vtkNew<vtkXMLImageDataReader> reader;
    failOnVtkErrors(reader);
    reader->SetFileName(file.c_str());
    reader->Update();
    return reader->GetOutput();
}

/// The point array called name with the expected VTK type and components (fails if absent).
vtkDataArray* pointArray(vtkDataSet* data, const char* name, int vtkType, int components) {
    vtkDataArray* array = data->GetPointData()->GetArray(name);
    EXPECT_NE(array, nullptr) << "no point array " << name;
    if (array == nullptr) return nullptr;
    EXPECT_EQ(array->GetDataType(), vtkType) << name;
    EXPECT_EQ(array->GetNumberOfComponents(), components) << name;
    EXPECT_EQ(array->GetNumberOfTuples(), data->GetNumberOfPoints()) << name;
    return array;
}

/// Three particles with values that survive only a bit-exact round trip.
struct KnownFrame {
    std::vector<std::uint64_t> id{0, 7, (std::uint64_t{1} << 40) + 3};
    std::vector<Vec3> position{{0.1, -0.2, 0.3}, {1.0 / 3, 2e-7, -5.5}, {1e3, 0, -1e-12}};
    std::vector<Vec3> velocity{{3, 4, 0}, {-1.0 / 7, 0.25, 1e-9}, {0, 0, 0}};
    std::vector<double> radius{5e-6, 1.0 / 3 * 1e-4, 2.5e-3};
    std::vector<std::int32_t> state{static_cast<std::int32_t>(ParticleState::active),
                                    static_cast<std::int32_t>(ParticleState::arrived),
                                    static_cast<std::int32_t>(ParticleState::escaped)};

    ParticleFrame frame() const { return {id, position, velocity, radius, state}; }
};

TEST_F(VtkOutput, ParticleFrameReadsBackBitForBit) {
    const KnownFrame known;
    const fs::path file = directory_ / "particles_000000.vtp";
    writeParticlesVtp(file, known.frame());

    const std::string xml = contents(file);
    EXPECT_NE(xml.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos);
    EXPECT_NE(xml.find("format=\"appended\""), std::string::npos);
    EXPECT_NE(xml.find("encoding=\"raw\""), std::string::npos);

    const auto data = readVtp(file);
    ASSERT_EQ(data->GetNumberOfPoints(), 3);
    EXPECT_EQ(data->GetPoints()->GetDataType(), VTK_DOUBLE);
    ASSERT_EQ(data->GetNumberOfVerts(), 3);
    EXPECT_EQ(data->GetNumberOfCells(), 3);
    auto* id = pointArray(data, "id", VTK_TYPE_INT64, 1);
    auto* diameter = pointArray(data, "diameter", VTK_DOUBLE, 1);
    auto* velocity = pointArray(data, "velocity", VTK_DOUBLE, 3);
    auto* speed = pointArray(data, "speed", VTK_DOUBLE, 1);
    auto* state = pointArray(data, "state", VTK_TYPE_INT32, 1);
    ASSERT_TRUE(id && diameter && velocity && speed && state);
    EXPECT_STREQ(data->GetPointData()->GetScalars()->GetName(), "speed");

    vtkNew<vtkIdList> cellPoints;
    for (vtkIdType n = 0; n < 3; ++n) {
        const auto i = static_cast<std::size_t>(n);
        data->GetVerts()->GetCellAtId(n, cellPoints);
        ASSERT_EQ(cellPoints->GetNumberOfIds(), 1);
        EXPECT_EQ(cellPoints->GetId(0), n);
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(data->GetPoint(n)[c], known.position[i][c]) << n;
            EXPECT_EQ(velocity->GetComponent(n, c), known.velocity[i][c]) << n;
        }
        EXPECT_EQ(static_cast<std::uint64_t>(id->GetVariantValue(n).ToTypeInt64()), known.id[i]);
        EXPECT_EQ(diameter->GetComponent(n, 0), 2 * known.radius[i]);
        EXPECT_EQ(speed->GetComponent(n, 0), known.velocity[i].norm());
        EXPECT_EQ(state->GetComponent(n, 0), known.state[i]);
    }
    EXPECT_EQ(speed->GetComponent(0, 0), 5.0);
    EXPECT_EQ(filesPresent(), std::vector<std::string>{"particles_000000.vtp"});
}

TEST_F(VtkOutput, EmptyFrameIsAValidEmptyDataset) {
    const fs::path file = directory_ / "empty.vtp";
    writeParticlesVtp(file, ParticleFrame{});

    const auto data = readVtp(file);
    EXPECT_EQ(data->GetNumberOfPoints(), 0);
    EXPECT_EQ(data->GetNumberOfVerts(), 0);
    // The arrays are declared even when empty, so a series keeps the same fields in every frame.
    EXPECT_NE(pointArray(data, "id", VTK_TYPE_INT64, 1), nullptr);
    EXPECT_NE(pointArray(data, "diameter", VTK_DOUBLE, 1), nullptr);
    EXPECT_NE(pointArray(data, "velocity", VTK_DOUBLE, 3), nullptr);
    EXPECT_NE(pointArray(data, "speed", VTK_DOUBLE, 1), nullptr);
    EXPECT_NE(pointArray(data, "state", VTK_TYPE_INT32, 1), nullptr);
}

TEST_F(VtkOutput, FrameCarriesExactlyTheSelectedFields) {
    // output { fields (velocity state); }: only those arrays, still bit-exact; no active
    // scalar, since speed is not written.
    const KnownFrame known;
    ParticleFrame frame = known.frame();
    frame.fields = ParticleFieldSet().add(ParticleField::velocity).add(ParticleField::state);
    const fs::path file = directory_ / "selected.vtp";
    writeParticlesVtp(file, frame);

    const auto data = readVtp(file);
    ASSERT_EQ(data->GetNumberOfPoints(), 3);
    EXPECT_EQ(data->GetPointData()->GetNumberOfArrays(), 2);
    auto* velocity = pointArray(data, "velocity", VTK_DOUBLE, 3);
    auto* state = pointArray(data, "state", VTK_TYPE_INT32, 1);
    ASSERT_TRUE(velocity && state);
    EXPECT_EQ(data->GetPointData()->GetScalars(), nullptr);
    for (vtkIdType n = 0; n < 3; ++n) {
        const auto i = static_cast<std::size_t>(n);
        EXPECT_EQ(velocity->GetComponent(n, 1), known.velocity[i][1]);
        EXPECT_EQ(state->GetComponent(n, 0), known.state[i]);
    }
}

TEST_F(VtkOutput, FrameCarriesTemperatureAndSpinOnlyWhereTracked) {
    // With heat transfer and spin the frame has both arrays, bit-exact; without them neither,
    // though every field is asked for.
    const KnownFrame known;
    const std::vector<double> temperature{300, 1.0 / 3 + 400, 1e3};
    const std::vector<Vec3> spin{{1e4, -2, 0}, {0, 0, 1.0 / 7}, {-5e-3, 3e5, 1}};
    ParticleFrame frame = known.frame();
    frame.temperature = temperature;
    frame.angularVelocity = spin;
    writeParticlesVtp(directory_ / "tracked.vtp", frame);
    writeParticlesVtp(directory_ / "untracked.vtp", known.frame());

    const auto data = readVtp(directory_ / "tracked.vtp");
    auto* heat = pointArray(data, "temperature", VTK_DOUBLE, 1);
    auto* omega = pointArray(data, "angularVelocity", VTK_DOUBLE, 3);
    ASSERT_TRUE(heat && omega);
    for (vtkIdType n = 0; n < 3; ++n) {
        const auto i = static_cast<std::size_t>(n);
        EXPECT_EQ(heat->GetComponent(n, 0), temperature[i]);
        for (int c = 0; c < 3; ++c) EXPECT_EQ(omega->GetComponent(n, c), spin[i][c]);
    }
    const auto plain = readVtp(directory_ / "untracked.vtp");
    EXPECT_EQ(plain->GetPointData()->GetArray("temperature"), nullptr);
    EXPECT_EQ(plain->GetPointData()->GetArray("angularVelocity"), nullptr);
    EXPECT_EQ(plain->GetPointData()->GetNumberOfArrays(), 5);
}

TEST_F(VtkOutput, FrameCarriesChargeOnlyWhenCharged) {
    // Electromagnetic forces (physics/electromagnetic.h): the charge array, bit-exact, read back
    // for a restart's rewrite; an uncharged frame has none.
    const KnownFrame known;
    const std::vector<double> charge{1.6e-12, -1.0 / 3 * 1e-15, 0};
    ParticleFrame frame = known.frame();
    frame.charge = charge;
    writeParticlesVtp(directory_ / "charged.vtp", frame);
    const auto data = readVtp(directory_ / "charged.vtp");
    auto* array = pointArray(data, "charge", VTK_DOUBLE, 1);
    ASSERT_TRUE(array);
    for (vtkIdType n = 0; n < 3; ++n)
        EXPECT_EQ(array->GetComponent(n, 0), charge[static_cast<std::size_t>(n)]);
    const StoredParticleFrame stored = readParticlesVtp(directory_ / "charged.vtp");
    EXPECT_EQ(stored.charge, charge);
    const ParticleFrame again = stored.view(ParticleFieldSet::all(), false, false, true);
    ASSERT_TRUE(again.charge.has_value());
    EXPECT_EQ(again.charge->size(), 3u);
    writeParticlesVtp(directory_ / "uncharged.vtp", known.frame());
    EXPECT_EQ(readVtp(directory_ / "uncharged.vtp")->GetPointData()->GetArray("charge"), nullptr);
}

TEST_F(VtkOutput, FrameWithMismatchedArraysIsRejected) {
    KnownFrame known;
    ParticleFrame shortSpin = known.frame();
    const std::vector<Vec3> twoSpins(2, Vec3::Zero());
    shortSpin.angularVelocity = twoSpins;
    EXPECT_THROW(writeParticlesVtp(directory_ / "bad.vtp", shortSpin), std::invalid_argument);
    known.radius.pop_back();
    EXPECT_THROW(writeParticlesVtp(directory_ / "bad.vtp", known.frame()), std::invalid_argument);
    EXPECT_TRUE(filesPresent().empty());
}

/// The (timestep, file) pairs of a .pvd, parsed as XML.
std::vector<std::pair<double, std::string>> pvdEntries(const fs::path& file) {
    vtkNew<vtkXMLDataParser> parser;
    parser->SetFileName(file.c_str());
    EXPECT_EQ(parser->Parse(), 1) << "not valid XML: " << file;
    vtkXMLDataElement* root = parser->GetRootElement();
    EXPECT_NE(root, nullptr);
    if (root == nullptr) return {};
    EXPECT_STREQ(root->GetName(), "VTKFile");
    EXPECT_STREQ(root->GetAttribute("type"), "Collection");
    vtkXMLDataElement* collection = root->FindNestedElementWithName("Collection");
    EXPECT_NE(collection, nullptr);
    if (collection == nullptr) return {};
    std::vector<std::pair<double, std::string>> entries;
    for (int n = 0; n < collection->GetNumberOfNestedElements(); ++n) {
        vtkXMLDataElement* dataSet = collection->GetNestedElement(n);
        EXPECT_STREQ(dataSet->GetName(), "DataSet");
        entries.emplace_back(std::stod(dataSet->GetAttribute("timestep")),
                             dataSet->GetAttribute("file"));
    }
    return entries;
}

TEST_F(VtkOutput, PvdListsEveryFrameWithExactTimesAfterEachAdd) {
    const fs::path file = directory_ / "particles.pvd";
    PvdSeries series(file);
    EXPECT_EQ(series.file(), file);
    const std::vector<std::pair<double, std::string>> frames{
        {0.0, "particles_000000.vtp"},
        {0.1, "particles_000001.vtp"},
        {1e-5 / 3, "frames/particles_000002.vtp"},
        {2.0 / 3, "a&b \"<odd>\".vtp"}};
    for (std::size_t n = 0; n < frames.size(); ++n) {
        series.add(frames[n].first, frames[n].second);
        const auto entries = pvdEntries(file);
        ASSERT_EQ(entries.size(), n + 1);
        for (std::size_t k = 0; k <= n; ++k) {
            EXPECT_EQ(entries[k].first, frames[k].first) << k; // bit for bit
            EXPECT_EQ(entries[k].second, frames[k].second) << k;
        }
    }
    EXPECT_EQ(filesPresent(), std::vector<std::string>{"particles.pvd"});
}

TEST_F(VtkOutput, FailedPvdRewriteLeavesNoEntryBehind) {
    const fs::path run = directory_ / "run";
    PvdSeries series(run / "particles.pvd");
    EXPECT_THROW(series.add(1.0, "lost.vtp"), OutputError); // run/ does not exist yet
    fs::create_directory(run);
    series.add(2.0, "kept.vtp");
    const auto entries = pvdEntries(run / "particles.pvd");
    ASSERT_EQ(entries.size(), 1u);
    EXPECT_EQ(entries[0].first, 2.0);
    EXPECT_EQ(entries[0].second, "kept.vtp");
}

/// U = A x + b, exact in binary on a dyadic lattice; counts its sample() calls.
class LinearFlow : public CarrierField {
public:
    LinearFlow() {
        gradient_ << 1, 2, 0, -0.5, 0, 4, 0.25, -3, 1;
        offset_ << 10, -20, 0.5;
    }
    void sample(std::span<const Vec3> points, double time, CarrierNeeds needs,
                CarrierSample& out) const override {
        ++calls;
        lastBatchSize = points.size();
        lastTime = time;
        out.resize(points.size(), needs);
        for (std::size_t i = 0; i < points.size(); ++i) out.velocity[i] = at(points[i]);
    }
    std::string describe() const override { return "linear test flow"; }
    Vec3 at(const Vec3& x) const { return gradient_ * x + offset_; }

    mutable int calls = 0;
    mutable std::size_t lastBatchSize = 0;
    mutable double lastTime = -1;

private:
    Mat3 gradient_;
    Vec3 offset_;
};

TEST_F(VtkOutput, CarrierLatticeCarriesTheFieldInOneBatch) {
    const LinearFlow flow;
    const Box box{Vec3(-1, 0, -0.5), Vec3(1, 2, 0.5)};
    const fs::path file = directory_ / "carrier.vti";
    writeCarrierVti(file, flow, box, {5, 3, 2}, 0.125);
    EXPECT_EQ(flow.calls, 1);
    EXPECT_EQ(flow.lastBatchSize, 30u);
    EXPECT_EQ(flow.lastTime, 0.125);

    const auto image = readVti(file);
    int dimensions[3];
    image->GetDimensions(dimensions);
    EXPECT_EQ(dimensions[0], 5);
    EXPECT_EQ(dimensions[1], 3);
    EXPECT_EQ(dimensions[2], 2);
    const Vec3 spacing(0.5, 1, 1);
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_EQ(image->GetOrigin()[axis], box.min[axis]);
        EXPECT_EQ(image->GetSpacing()[axis], spacing[axis]);
    }
    ASSERT_EQ(image->GetNumberOfPoints(), 30);
    auto* u = pointArray(image, "U", VTK_DOUBLE, 3);
    auto* magU = pointArray(image, "magU", VTK_DOUBLE, 1);
    ASSERT_TRUE(u && magU);
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 5; ++i) {
                int ijk[3] = {i, j, k};
                const vtkIdType n = image->ComputePointId(ijk);
                const Vec3 x = box.min + Vec3(i, j, k).cwiseProduct(spacing);
                const Vec3 expected = flow.at(x);
                for (int c = 0; c < 3; ++c) {
                    EXPECT_EQ(image->GetPoint(n)[c], x[c]) << n;
                    EXPECT_EQ(u->GetComponent(n, c), expected[c]) << n;
                }
                EXPECT_EQ(magU->GetComponent(n, 0), expected.norm()) << n;
            }
    // The far corner (1, 2, 0.5): U = (1 + 4, -0.5 + 2, 0.25 - 6 + 0.5) + b.
    EXPECT_EQ(u->GetComponent(29, 0), 15.0);
    EXPECT_EQ(u->GetComponent(29, 1), -18.5);
    EXPECT_EQ(u->GetComponent(29, 2), -4.75);
    vtkDataArray* time = image->GetFieldData()->GetArray("TimeValue");
    ASSERT_NE(time, nullptr);
    EXPECT_EQ(time->GetComponent(0, 0), 0.125);
}

TEST_F(VtkOutput, CarrierLatticeWithAFlatAxisLiesAtBoxMin) {
    const LinearFlow flow;
    const Box box{Vec3(0, 0, 0.25), Vec3(1, 1, 0.75)};
    writeCarrierVti(directory_ / "slice.vti", flow, box, {3, 2, 1}, 0.0);
    const auto image = readVti(directory_ / "slice.vti");
    ASSERT_EQ(image->GetNumberOfPoints(), 6);
    auto* u = pointArray(image, "U", VTK_DOUBLE, 3);
    ASSERT_NE(u, nullptr);
    for (vtkIdType n = 0; n < 6; ++n) {
        const Vec3 x(image->GetPoint(n)[0], image->GetPoint(n)[1], image->GetPoint(n)[2]);
        EXPECT_EQ(x.z(), 0.25);
        for (int c = 0; c < 3; ++c) EXPECT_EQ(u->GetComponent(n, c), flow.at(x)[c]);
    }
    EXPECT_THROW(writeCarrierVti(directory_ / "none.vti", flow, box, {3, 0, 1}, 0.0),
                 std::invalid_argument);
    EXPECT_FALSE(fs::exists(directory_ / "none.vti"));
}

TEST_F(VtkOutput, AtomicWriteReplacesTheWholeFile) {
    const fs::path file = directory_ / "summary.json";
    writeTextAtomically(file, "a much longer first version\n");
    writeTextAtomically(file, "second\n");
    EXPECT_EQ(contents(file), "second\n");
    writeTextAtomically(file, "");
    EXPECT_EQ(contents(file), "");
    EXPECT_EQ(filesPresent(), std::vector<std::string>{"summary.json"});
}

TEST_F(VtkOutput, ThrowingWriterLeavesOriginalAndNoTemporary) {
    const fs::path file = directory_ / "particles_000003.vtp";
    writeTextAtomically(file, "original");
    struct WriterFailed {};
    fs::path temporaryUsed;
    EXPECT_THROW(writeFileAtomically(file,
                                     [&](const fs::path& temporary) {
                                         temporaryUsed = temporary;
                                         std::ofstream(temporary) << "half a fi";
                                         throw WriterFailed{};
                                     }),
                 WriterFailed);
    EXPECT_EQ(temporaryUsed,
              directory_ / ("particles_000003.vtp.tmp-" + std::to_string(::getpid())));
    EXPECT_EQ(contents(file), "original");
    EXPECT_EQ(filesPresent(), std::vector<std::string>{"particles_000003.vtp"});
}

TEST_F(VtkOutput, FailedRenameKeepsTargetAndRemovesTemporary) {
    // A non-empty directory in the target's place cannot be renamed over.
    const fs::path target = directory_ / "carrier.vti";
    fs::create_directories(target / "inside");
    try {
        writeTextAtomically(target, "new");
        FAIL() << "no OutputError";
    } catch (const OutputError& error) {
        EXPECT_NE(std::string(error.what()).find(target.string()), std::string::npos)
            << error.what();
    }
    EXPECT_TRUE(fs::is_directory(target / "inside"));
    EXPECT_EQ(filesPresent(), std::vector<std::string>{"carrier.vti"});
}

/// The OutputError message of call, empty (and a test failure) if it throws none.
template <typename Call> std::string outputErrorOf(Call call) {
    try {
        call();
    } catch (const OutputError& error) {
        return error.what();
    }
    ADD_FAILURE() << "no OutputError";
    return "";
}

TEST_F(VtkOutput, UnwritableDirectoryGivesOutputErrorNamingPathAndReason) {
    const fs::path missing = directory_ / "missing" / "particles.pvd";
    std::string message = outputErrorOf([&] { writeTextAtomically(missing, "x"); });
    EXPECT_NE(message.find(missing.string()), std::string::npos) << message;
    EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;

    writeTextAtomically(directory_ / "plain", "a file, not a directory");
    const fs::path underFile = directory_ / "plain" / "particles_000000.vtp";
    const KnownFrame known;
    const fs::path vti = directory_ / "missing" / "carrier.vti";
    // The one OutputError is the whole report: VTK's writers print nothing of their own.
    testing::internal::CaptureStderr();
    message = outputErrorOf([&] { writeParticlesVtp(underFile, known.frame()); });
    const std::string vtiMessage = outputErrorOf([&] {
        writeCarrierVti(vti, LinearFlow{}, Box{}, {2, 2, 2}, 0);
    });
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
    EXPECT_NE(message.find(underFile.string()), std::string::npos) << message;
    EXPECT_NE(message.find("Not a directory"), std::string::npos) << message;
    EXPECT_NE(vtiMessage.find(vti.string()), std::string::npos) << vtiMessage;
    EXPECT_EQ(filesPresent(), std::vector<std::string>{"plain"});
}

} // namespace
} // namespace slides
