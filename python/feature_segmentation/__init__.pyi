# SPDX-License-Identifier: GPL-3.0-or-later
from typing import Any, Tuple

import numpy as np
import numpy.typing as npt

from ._core import Result as Result, Segmentation as Segmentation, read_mesh as read_mesh, \
    segment_file as segment_file

def segment(vertices: npt.ArrayLike, faces: npt.ArrayLike, **options: Any
            ) -> Tuple[npt.NDArray[np.int64], npt.NDArray[np.int64], Result]: ...
