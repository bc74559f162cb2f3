// metricmap.set_memory_budget / memory_budget: the process-wide budget the library checks before
// large allocations driven by input (the CLI's --max-memory).
#include <cstdint>
#include <string>

#include <pybind11/pybind11.h>

#include "metricmap/common/memory_budget.h"

namespace py = pybind11;

namespace metricmap::python {

void initMemory(py::module_& m) {
  m.def(
      "set_memory_budget",
      [](const py::object& size) {
        std::uint64_t bytes = 0;
        if (py::isinstance<py::str>(size)) {
          bytes = parseByteSize(size.cast<std::string>(), "memory budget");
        } else if (py::isinstance<py::int_>(size) && !py::isinstance<py::bool_>(size)) {
          const py::int_ n = size.cast<py::int_>();
          if (n < py::int_(1) || n > py::int_(UINT64_MAX))
            throw py::value_error("memory budget must be a positive number of bytes, got " +
                                  py::repr(size).cast<std::string>());
          bytes = n.cast<std::uint64_t>();
        } else {
          throw py::type_error("memory budget must be an int (bytes) or a text like '2G', got " +
                               std::string(py::str(py::type::of(size).attr("__name__"))));
        }
        setMemoryBudget(bytes);
      },
      py::arg("size"), R"doc(
Set the memory budget the library checks before large allocations (the CLI's ``--max-memory``).

Parameters
----------
size : int or str
    Bytes (> 0), or a text such as ``"512M"``, ``"2G"``, ``"1.5G"`` (K, M, G, T: powers of 1024).

Raises
------
ValueError
    0, negative, or a text that is not a size. TypeError: another type.
)doc");
  m.def("memory_budget", &memoryBudget,
        "The memory budget in bytes (default: half of the physical memory, at least 256 MiB); "
        "a result that would need more raises CapacityError.");
}

}  // namespace metricmap::python
