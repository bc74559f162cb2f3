"""`repr()` with the values that tell objects apart, for the compiled classes whose state is
read through their public attributes."""


def _height_map(self):
    s = self.statistics
    h, w, bins = self.counts.shape
    return f"<metricmap.HeightMap {h} x {w} cells, {bins} height bins, {s.get('frames', 0)} frames>"


def _distance_field(self):
    return (f"<metricmap.DistanceField shape={tuple(self.shape)} resolution={self.resolution!r} "
            f"origin={tuple(float(v) for v in self.origin)} max_distance={self.max_distance!r}>")


def _localization_run(self):
    return (f"<metricmap.LocalizationRun {len(self.frames)} scans, "
            f"{int(sum(bool(v) for v in self.localised))} localised>")


def _localizer(self):
    return f"<metricmap.Localizer2D status={self.status!r}>"


def _sequence_mapper(self):
    return f"<metricmap.SequenceMapper {len(self.poses)} poses built>"


def _slam3d(self):
    return f"<metricmap.Slam3D {len(self.poses)} scans, {len(self.loops)} loops>"


def install(module):
    module.HeightMap.__repr__ = _height_map
    module.DistanceField.__repr__ = _distance_field
    module.LocalizationRun.__repr__ = _localization_run
    module.Localizer2D.__repr__ = _localizer
    module.SequenceMapper.__repr__ = _sequence_mapper
    module.Slam3D.__repr__ = _slam3d
