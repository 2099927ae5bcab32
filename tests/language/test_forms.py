"""rootlang/forms.py is the one description of the language: what the checks and the runtime
read from it (words, the meaning of each choice, every robot event's packet) covers it all."""

from __future__ import annotations

import typing

from rootlang import ast, forms
from rootlang.grammar import lark_parser
from rootlang.grammar.words import terminal_words
from rootlang.locale.keywords import KEYWORDS
from rootlang.protocol.enums import BumperState, LightState, TouchSensors
from rootlang.runtime.interpreter import bumper_pressed, touch_sensors
from rootlang.units import (
    FUNCTIONS,
    ONE_VALUE_FUNCTIONS,
    Kind,
    Quantity,
    Written,
    apply_function,
    function_kind,
)


def every_subclass(base: type[ast.Node]) -> set[type[ast.Node]]:
    """The node types of rootlang.ast below ``base`` (as the module names them: a slotted
    dataclass replaces the class it was made from)."""
    return {
        value
        for value in vars(ast).values()
        if isinstance(value, type) and issubclass(value, base) and value is not base
    }


def test_every_event_is_the_robots_or_the_programs() -> None:
    robot, program = set(typing.get_args(ast.RobotEvent)), set(typing.get_args(ast.ProgramEvent))
    assert every_subclass(ast.Event) == robot | program
    assert not robot & program
    # a robot event has its packet and feature (and its edge test: a `match` mypy checks)
    assert set(forms.EVENTS) == robot


def test_every_choice_with_meanings_means_something_for_each_option() -> None:
    sensors = [sensor.form for sensor in forms.SENSORS.values()]
    choices = [
        part
        for form in (*forms.STATEMENT_FORMS, *forms.EVENT_FORMS, *sensors)
        for part in form.parts
        if isinstance(part, forms.Choice) and part.meanings
    ]
    assert len(choices) >= 6  # touch, colour zone, obstacle side: event and sensor; light
    for choice in choices:
        assert {value for value, _ in choice.options} <= set(choice.meanings)


def test_the_meanings_name_the_protocols_own_values() -> None:
    for groups in forms.BUMPER_SIDE.meanings.values():
        assert all(BumperState[name] in BumperState for group in groups for name in group)
    assert bumper_pressed(BumperState.LEFT, "any") and not bumper_pressed(BumperState.LEFT, "both")
    assert bumper_pressed(BumperState.BOTH, "both") and not bumper_pressed(BumperState.NONE, "any")
    for state in forms.LIGHT_STATE.meanings.values():
        assert LightState[state] in LightState
    assert touch_sensors("any") == ~TouchSensors.NONE
    assert touch_sensors("back left") == TouchSensors.REAR_LEFT
    assert list(forms.COLOR_ZONE.meaning("middle")) == list(range(10, 22))


def test_the_words_a_statement_or_event_starts_with_come_from_the_forms() -> None:
    assert {"move", "forever", "if", "else", "print", "dock", "undock", "marker"} <= (
        forms.STATEMENT_WORDS
    )
    assert {"bumped", "docked", "undocked", "color", "message"} <= forms.EVENT_WORDS
    assert "when" not in forms.STATEMENT_WORDS  # a header word, not a statement's


def test_each_built_in_function_is_one_entry_the_grammar_and_the_keywords_follow() -> None:
    words = terminal_words(lark_parser())
    by_way = {
        way: {name for name, function in FUNCTIONS.items() if function.written is way}
        for way in Written
    }
    assert set(words["FUNCTION1"]) == by_way[Written.ONE_VALUE] == set(ONE_VALUE_FUNCTIONS)
    assert set(words["FUNCTION2"]) == by_way[Written.BRACKETS]
    for function in FUNCTIONS.values():
        translated = [row for row in KEYWORDS if row[0] == function.name]
        assert translated == ([(function.name, *function.words)] if any(function.words) else [])
    assert apply_function("round", [Quantity.number(2.5)]) == Quantity.number(3)
    assert function_kind("sin", [Kind.ANGLE]) is Kind.NUMBER


def test_the_unions_that_handlers_match_on_hold_every_node_type() -> None:
    # a node type left out of its union would escape the `match` that mypy checks
    statements = every_subclass(ast.Statement) - {ast.FormStatement}  # a base, not a statement
    assert set(typing.get_args(ast.AnyStatement)) == statements
    assert set(typing.get_args(ast.AnyExpression)) == every_subclass(ast.Expression)


def test_the_syntax_trees_choice_types_hold_the_forms_options() -> None:
    # mypy needs each choice as a Literal type in rootlang.ast, written by hand: it must say
    # what the forms read and build, no more and no less
    checked = 0
    for form_node in {form.node for form in forms.every_form()}:
        for name, hint in typing.get_type_hints(form_node).items():
            if typing.get_origin(hint) is not typing.Literal:
                continue
            built = set()
            for form in forms.every_form():
                if form.node is not form_node:
                    continue
                built |= {form.fixed[name]} if name in form.fixed else set()
                for part in form.parts:
                    if isinstance(part, forms.Choice) and part.field == name:
                        built |= {value for value, _ in part.options} | set(part.also.values())
            assert set(typing.get_args(hint)) == built, (form_node.__name__, name)
            checked += 1
    assert checked >= 10  # direction, side, sensor, zone, state, mode, tool, target ...


def test_every_feature_a_form_needs_is_one_the_packet_table_tells() -> None:
    # which robot has a feature is the packet table's (forms.FEATURES names its packet): a
    # statement's, an event's and a sensor's feature all come from there
    from rootlang import forms
    from rootlang.checks import robots_with
    from rootlang.protocol import spec
    from rootlang.robots import RobotModel

    named = {feature for needs in forms.NEEDS.values() for feature, _ in needs.by_value.values()}
    named |= {needs.feature for needs in forms.NEEDS.values() if needs.feature}
    named |= {source.feature for source in forms.EVENTS.values()}
    named |= {sensor.feature for sensor in forms.SENSORS.values() if sensor.feature}
    assert named <= set(forms.FEATURES)
    for feature, packet in forms.FEATURES.items():
        assert robots_with(feature) <= spec(packet).robots, feature
    assert robots_with("eraser") == {RobotModel.RT1}
    assert robots_with("marker") == {RobotModel.RT0, RobotModel.RT1}
    assert robots_with("dock") == {RobotModel.CREATE3}


def test_the_statements_that_move_are_those_whose_forms_say_so() -> None:
    from rootlang import ast, forms

    moving = {ast.Move, ast.Turn, ast.Arc, ast.GoTo, ast.SetWheels, ast.Drive, ast.Dock}
    assert moving <= set(forms.MOTION)  # (and a new statement that moves, by its form alone)
    assert not {ast.StopMoving, ast.Tool, ast.Light, ast.PlayNote, ast.Say} & set(forms.MOTION)
    assert all(form.moves == (form.node in forms.MOTION) for form in forms.STATEMENT_FORMS)
