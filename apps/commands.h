#pragma once
/// \file commands.h
/// \brief Each subcommand registers its options and its action on the `metricmap` app.

#include <CLI/CLI.hpp>

namespace metricmap::cli {

void addInfoCommand(CLI::App& app);
void addGridCommand(CLI::App& app);
void addOctreeCommand(CLI::App& app);
void addCompareCommand(CLI::App& app);
void addLinesCommand(CLI::App& app);
void addDepthToCloudCommand(CLI::App& app);
void addHeightMapCommand(CLI::App& app);
void addKittiCommand(CLI::App& app);
void addOdometryCommand(CLI::App& app);
void addMapCommand(CLI::App& app);
void addViewCommand(CLI::App& app);
void addOccupancyCommand(CLI::App& app);
void addEvaluateCommand(CLI::App& app);
void addPoseGraphCommand(CLI::App& app);
void addSlam2DCommand(CLI::App& app);
void addSlam3DCommand(CLI::App& app);
void addLocalizeCommand(CLI::App& app);
void addDistanceCommand(CLI::App& app);

}  // namespace metricmap::cli
