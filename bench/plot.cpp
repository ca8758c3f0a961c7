// conescope-bench-plot: bar chart of cull efficiency per mesh from the report's summary.csv (first
// column the mesh, then one column per series), drawn with VTK charts and saved as PNG.
// Needs an X display: run it under xvfb-run.
//
//   conescope-bench-plot summary.csv efficiency.png
#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPen.h>
#include <vtkPlotBar.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkStringArray.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>

#include <array>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

std::vector<std::string> splitCsv(const std::string& line) {
    std::vector<std::string> fields;
    std::stringstream stream(line);
    std::string field;
    while (std::getline(stream, field, ',')) fields.push_back(field);
    return fields;
}

struct Series {
    std::vector<std::string> names;                // one per series
    std::vector<std::string> meshes;
    std::vector<std::vector<double>> values;       // [series][mesh]
};

Series readSummary(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    std::string line;
    if (!std::getline(in, line)) throw std::runtime_error(path + ": empty");
    Series series;
    const std::vector<std::string> header = splitCsv(line);
    series.names.assign(header.begin() + 1, header.end());
    series.values.resize(series.names.size());
    while (std::getline(in, line)) {
        const std::vector<std::string> fields = splitCsv(line);
        if (fields.size() != header.size()) continue;
        series.meshes.push_back(fields[0]);
        for (size_t s = 0; s < series.names.size(); ++s) series.values[s].push_back(std::stod(fields[s + 1]));
    }
    if (series.meshes.empty()) throw std::runtime_error(path + ": no rows");
    return series;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::cerr << "usage: conescope-bench-plot summary.csv efficiency.png\n";
        return 2;
    }
    try {
        const Series series = readSummary(argv[1]);
        vtkNew<vtkTable> table;
        vtkNew<vtkFloatArray> position;
        position->SetName("mesh index");
        table->AddColumn(position);
        for (const std::string& name : series.names) {
            vtkNew<vtkFloatArray> column;
            column->SetName(name.c_str());
            table->AddColumn(column);
        }
        table->SetNumberOfRows(vtkIdType(series.meshes.size()));
        for (size_t m = 0; m < series.meshes.size(); ++m) {
            table->SetValue(vtkIdType(m), 0, double(m + 1));
            for (size_t s = 0; s < series.names.size(); ++s) table->SetValue(vtkIdType(m), vtkIdType(s + 1), series.values[s][m]);
        }

        vtkNew<vtkContextView> view;
        view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
        view->GetRenderWindow()->SetSize(1400, 700);
        view->GetRenderWindow()->SetMultiSamples(0);
        vtkNew<vtkChartXY> chart;
        view->GetScene()->AddItem(chart);
        chart->SetTitle("Back-face cull efficiency per mesh (distance 3, budget 64/124, 128 views)");
        chart->GetTitleProperties()->SetFontSize(18);
        chart->SetShowLegend(true);
        chart->GetLegend()->SetHorizontalAlignment(vtkChartLegend::RIGHT);
        chart->GetLegend()->SetVerticalAlignment(vtkChartLegend::TOP);
        chart->GetLegend()->GetLabelProperties()->SetFontSize(14);
        chart->SetBarWidthFraction(0.8f);
        // Grey for meshoptimizer's baselines, a strong blue for ConeScope (the last series).
        const std::vector<std::array<unsigned char, 3>> colors = {{150, 150, 150}, {95, 95, 95}, {40, 40, 40}};
        for (size_t s = 0; s < series.names.size(); ++s) {
            vtkPlotBar* bar = vtkPlotBar::SafeDownCast(chart->AddPlot(vtkChart::BAR));
            bar->SetInputData(table, 0, vtkIdType(s + 1));
            const bool ours = s + 1 == series.names.size();
            const auto& color = ours ? std::array<unsigned char, 3>{31, 119, 180} : colors[s % colors.size()];
            bar->SetColor(color[0], color[1], color[2], 255);
            bar->SetLabel(series.names[s]);
        }
        vtkAxis* bottom = chart->GetAxis(vtkAxis::BOTTOM);
        vtkNew<vtkDoubleArray> ticks;
        vtkNew<vtkStringArray> labels;
        for (size_t m = 0; m < series.meshes.size(); ++m) {
            ticks->InsertNextValue(double(m + 1));
            labels->InsertNextValue(series.meshes[m]);
        }
        bottom->SetCustomTickPositions(ticks, labels);
        bottom->SetBehavior(vtkAxis::FIXED);
        bottom->SetRange(0.4, double(series.meshes.size()) + 0.6);
        bottom->SetTitle("mesh");
        bottom->GetLabelProperties()->SetFontSize(13);
        vtkAxis* left = chart->GetAxis(vtkAxis::LEFT);
        left->SetBehavior(vtkAxis::FIXED);
        left->SetRange(0.0, 1.0);
        left->SetTitle("efficiency (culled / back-facing triangles)");
        left->GetLabelProperties()->SetFontSize(13);

        view->GetRenderWindow()->Render();
        vtkNew<vtkWindowToImageFilter> capture;
        capture->SetInput(view->GetRenderWindow());
        capture->ReadFrontBufferOff();
        capture->Update();
        vtkNew<vtkPNGWriter> writer;
        writer->SetFileName(argv[2]);
        writer->SetInputConnection(capture->GetOutputPort());
        writer->Write();
        std::cerr << "wrote " << argv[2] << "\n";
    } catch (const std::exception& error) {
        std::cerr << "conescope-bench-plot: " << error.what() << "\n";
        return 1;
    }
    return 0;
}
