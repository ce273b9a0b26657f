"""Model files the benchmarks write themselves."""


def planar_chain(n, length=0.5, name=None):
    """The planar n-link pendulum: point masses on massless rods, absolute angles
    phi_i from the downward vertical, gravity; parameters m1, l1, ..., g."""
    lines = ['[model]', f'name = "{name or f"chain{n}"}"', f'title = "Planar {n}-link pendulum"']
    lines.append('[parameters]')
    lines += [f"m{i} = 1.0\nl{i} = {length}" for i in range(1, n + 1)] + ["g = 9.81", "[coordinates]"]
    lines += [f"phi{i} = {0.1 * i:.1f}" for i in range(1, n + 1)]
    for i in range(1, n + 1):
        x = " + ".join(f"l{j}*sin(phi{j})" for j in range(1, i + 1))
        y = " - ".join(f"l{j}*cos(phi{j})" for j in range(1, i + 1))
        lines.append(f'[[particles]]\nname = "b{i}"\nmass = "m{i}"\nposition = ["{x}", "-{y}", "0"]')
    lines.append('[gravity]\nacceleration = ["0", "-g", "0"]')
    return "\n".join(lines) + "\n"
