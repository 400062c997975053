"""The assertions of the Python tests in tests/ci: every failed check is printed and counted,
so that one run lists all that is wrong, not only the first."""

failures = []


def check(ok, message):
    if not ok:
        failures.append(message)
        print("FAIL:", message)


def verdict(passed_message):
    """The exit status of the test: 1 when a check failed, else 0 after printing the message."""
    if failures:
        return 1
    print(passed_message)
    return 0
