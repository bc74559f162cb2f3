"""Cell and voxel states as an IntEnum: the values of `LogOddsMap.states()` and
`DistanceField.states` (arrays of small integers, compared with these members)."""

import enum


class CellState(enum.IntEnum):
    """State of a voxel or cell: `states == CellState.OCCUPIED` selects the occupied ones."""

    UNKNOWN = 0
    FREE = 1
    OCCUPIED = 2
