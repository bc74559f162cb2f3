#pragma once
/// \file trajectory.h
/// \brief Forwarding header: the type lives in common/trajectory.h.

#include "metricmap/common/trajectory.h"
