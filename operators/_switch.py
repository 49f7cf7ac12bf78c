"""What the switches share: one operator a feature, `object.water_<feature>`, with an `enable`
property (on by default). Where on and off ask different things (floating, keep-out, the wake),
the class gives both checks, `enable_polls = {True: check, False: check}`, each `check(cls,
context)` written as a poll (`_poll.refuse`): a poll is a classmethod and cannot see `enable`,
so it lets through where either may run (`either_way`), and `execute` refuses the way that may
not (`refused_way`), in its poll's words. An old id that meant one way (`_aliases.FIXED`) polls
as that way alone."""


def either_way(cls, context):
    """The poll of a switch with `enable_polls`: where its on or its off may run. The off one is
    asked first, so that where neither may, the on one's message stands."""
    checks = cls.enable_polls
    return checks[False](cls, context) or checks[True](cls, context)


class _Heard:
    """Stands in for an operator class to hear what a poll check says."""

    message = None

    def poll_message_set(self, message, *_args):
        self.message = message


def way_allowed(cls, enable, context):
    """Whether the way `enable` of the switch `cls` may run: what its own poll was before the two
    ways became one operator (the panel greys each way's button by it)."""
    return bool(cls.enable_polls[enable](_Heard(), context))


def refused_way(operator, context):
    """Where the way `operator.enable` asks may not run (`either_way` let the other through):
    reports why, in the words of its poll, and returns {"CANCELLED"}; else None."""
    heard = _Heard()
    if operator.enable_polls[operator.enable](heard, context):
        return None
    operator.report({"ERROR"}, heard.message)
    return {"CANCELLED"}


def draw_switch(operator, keys):
    """A switch's redo panel: `enable` (unless hidden: an old id's fixed way, `_aliases.FIXED`),
    then the properties `keys` that only on takes."""
    layout = operator.layout
    layout.use_property_split, layout.use_property_decorate = True, False  # as Blender draws them
    if not operator.properties.bl_rna.properties["enable"].is_hidden:
        layout.prop(operator, "enable")
    if operator.enable:
        for key in keys:
            layout.prop(operator, key)
