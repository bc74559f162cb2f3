#pragma once
/// \file pose_relation.h
/// \brief Forwarding header: the type lives in common/pose_relation.h.

#include "metricmap/common/pose_relation.h"
