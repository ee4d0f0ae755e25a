package io.github.jdem846.tint;

/** A ramp whose stops are elevations (absolute stops, or percent stops already placed on a DEM's range). */
final class ElevationTint implements TintFunction {

    private final StopTable table;

    ElevationTint(StopTable table) {
        this.table = table;
    }

    @Override
    public int argb(float elevation) {
        return table.argb(elevation);
    }
}
