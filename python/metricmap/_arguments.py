"""Our own message for a call pybind11 cannot match: the unknown keyword names and the
parameters the function takes, instead of pybind11's list of overloads with the arguments'
values (which prints whole arrays)."""

import functools

_PYBIND_MISMATCH = ("incompatible function arguments", "incompatible constructor arguments")


def _parameters(doc, name):
    """Parameter names of the docstring's first line `name(a: T, b: T = 1, *, c: T) -> R`."""
    line = (doc or "").lstrip().splitlines()[0] if doc else ""
    if not line.startswith(name + "(") or ") ->" not in line:
        return None
    inner, depth, cur, parts = line[len(name) + 1 : line.rindex(") ->")], 0, "", []
    for ch in inner:
        depth += ch in "([{"
        depth -= ch in ")]}"
        if ch == "," and depth == 0:
            parts.append(cur)
            cur = ""
        else:
            cur += ch
    parts.append(cur)
    names = [p.split(":")[0].split("=")[0].strip() for p in parts if p.strip()]
    if any(n.startswith("*") and n != "*" for n in names):
        return None  # *args / **kwargs: overloads or open keywords, checked by the function
    return [n for n in names if n not in ("self", "*", "")]


def _type_names(args, kwargs):
    shown = [type(a).__name__ for a in args] + [f"{k}={type(v).__name__}" for k, v in kwargs.items()]
    return ", ".join(shown)


def _checked(fn, name, params, method=False):
    @functools.wraps(fn)
    def call(*args, **kwargs):
        try:
            return fn(*args, **kwargs)
        except TypeError as e:
            if not any(m in str(e) for m in _PYBIND_MISMATCH):
                raise
            given = args[1:] if method else args
            unknown = [k for k in kwargs if k not in params]
            takes = ", ".join(params)
            if unknown:
                message = (f"{name}() got unknown keyword argument{'s' if len(unknown) > 1 else ''} "
                           f"{', '.join(repr(k) for k in unknown)}; it takes: {takes}")
            else:
                message = (f"{name}() cannot take ({_type_names(given, kwargs)}): see "
                           f"help(metricmap.{name}); it takes: {takes}")
            raise TypeError(message) from None

    if not method:
        call.__module__ = "metricmap"  # pickle finds the function as metricmap.<name>
        call.__qualname__ = name
    return call


def install(namespace, names):
    """Wrap the compiled functions and the classes' constructors of `namespace` (a module's
    globals) named in `names`."""
    for name in names:
        obj = namespace.get(name)
        if isinstance(obj, type):
            init = obj.__dict__.get("__init__")
            params = _parameters(getattr(init, "__doc__", None), "__init__")
            if params is not None:
                obj.__init__ = _checked(init, obj.__name__, params, method=True)
        elif type(obj).__name__ == "builtin_function_or_method":
            params = _parameters(obj.__doc__, name)
            if params is not None:
                namespace[name] = _checked(obj, name, params)
