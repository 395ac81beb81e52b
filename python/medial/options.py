"""Keyword arguments to filter properties, named as the CLI's options in snake_case (`--nodes` is
`nodes`, `--no-refine` is `refine=False`). Values are checked against the range the filter declares, as the
CLI does; the filter is the one place that knows a default (docs/ARCHITECTURE.md §3)."""
from medial.errors import MedialError, _Messages, quiet_vtk


class Number:
    """A number property: Set<Property>, checked against Get<Property>MinValue/MaxValue; `turn_on`, a
    property switched on as well when the number is given (sharp_scale turns SharpScaling on)."""

    def __init__(self, prop, turn_on=None):
        self.prop, self.turn_on = prop, turn_on

    def default(self, vtk_filter):
        return getattr(vtk_filter, "Get" + self.prop)()

    def apply(self, vtk_filter, name, value):
        whole = isinstance(self.default(vtk_filter), int) and not isinstance(self.default(vtk_filter), bool)
        low = getattr(vtk_filter, "Get%sMinValue" % self.prop, lambda: float("-inf"))()
        high = getattr(vtk_filter, "Get%sMaxValue" % self.prop, lambda: float("inf"))()
        try:
            number = float(value)
        except (TypeError, ValueError):
            raise MedialError("%s must be a number, got %r" % (name, value)) from None
        if not (low <= number <= high) or (whole and number != int(number)):
            bound = (">= %g" % low) if high >= 2147483647 else ("in %g..%g" % (low, high))
            raise MedialError("%s must be %s %s, got %r" % (name, "a whole number" if whole else "a number",
                                                             bound, value))
        getattr(vtk_filter, "Set" + self.prop)(int(number) if whole else number)
        if self.turn_on:
            getattr(vtk_filter, "Set" + self.turn_on)(True)


class Flag:
    """An on/off property (Set<Property>(bool)); `inverted` for the CLI's flags that turn one off
    (`--triangle-fans` is PairTriangles off)."""

    def __init__(self, prop, inverted=False):
        self.prop, self.inverted = prop, inverted

    def default(self, vtk_filter):
        return bool(getattr(vtk_filter, "Get" + self.prop)()) != self.inverted

    def apply(self, vtk_filter, name, value):
        if not isinstance(value, (bool, int)) or value not in (0, 1):
            raise MedialError("%s must be True or False, got %r" % (name, value))
        getattr(vtk_filter, "Set" + self.prop)(bool(value) != self.inverted)


class Name:
    """A property chosen by name (Set<Property>(str)); the filter refuses unknown names with an error that
    lists the known ones."""

    def __init__(self, prop):
        self.prop = prop

    def default(self, vtk_filter):
        return getattr(vtk_filter, "Get" + self.prop)()

    def apply(self, vtk_filter, name, value):
        messages = _Messages()
        messages.watch(vtk_filter)
        with quiet_vtk():
            getattr(vtk_filter, "Set" + self.prop)(str(value))
        messages.release()
        if messages.errors:
            raise MedialError("%s: %s" % (name, messages.errors[0]))


def apply_options(vtk_filter, table, options, function):
    """Sets `vtk_filter`'s properties from the keyword arguments `options` of `function` by `table`
    (keyword -> Number, Flag or Name). An unknown keyword is a TypeError, as in any Python function."""
    for name, value in options.items():
        if name not in table:
            raise TypeError("%s() got an unexpected keyword argument %r (it takes: %s)"
                            % (function, name, ", ".join(sorted(table))))
        table[name].apply(vtk_filter, name, value)


def defaults(vtk_class, table):
    """The defaults of a fresh `vtk_class` filter, by keyword (for the docstrings)."""
    fresh = vtk_class()
    return {name: option.default(fresh) for name, option in table.items()}


def document(vtk_class, table):
    """Decorator: formats the function's docstring with the defaults of a fresh `vtk_class` ({nodes} ...)."""
    def decorate(function):
        function.__doc__ = function.__doc__.format(**{k: repr(v) for k, v in defaults(vtk_class, table).items()})
        return function
    return decorate
