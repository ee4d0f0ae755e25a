package io.github.jdem846.tint;

import io.github.jdem846.raster.ElevationStatistics;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Objects;
import java.util.function.ToDoubleFunction;

/**
 * A colour ramp given by stops: the built-in ramps other than {@code hypsometric-bathymetric} and {@code standard},
 * and every colour file.
 *
 * <p>Stops may be listed in any order and may mix units (a colour file can); binding places each stop on the
 * DEM's range and sorts them by position, keeping the listed order of stops at the same position (a hard step:
 * below it the ramp runs into the first of them, above it starts from the last). A ramp whose stops are all
 * percent is evaluated as the article writes it, through the ratio of eq. 1; one with absolute stops works on
 * elevations, with each percent stop placed at min + percent/100·(max − min) as gdaldem places it.
 *
 * @param name       a short name for messages
 * @param stops      at least one stop (copied)
 * @param selection  how colours between stops are chosen
 * @param noDataArgb the colour of no-data cells (NaN); {@code 0} = transparent
 */
public record StopRamp(String name, List<ColorStop> stops, ColorSelection selection, int noDataArgb)
        implements ColorRamp {

    /**
     * Checks that the name and selection are given, and copies the stops, of which there must be at least one.
     *
     * @param name a short name for messages
     * @param stops at least one stop (copied)
     * @param selection how colours between stops are chosen
     * @param noDataArgb the colour of no-data cells (NaN); {@code 0} = transparent
     */
    public StopRamp {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(selection, "selection");
        stops = List.copyOf(stops);
        if (stops.isEmpty()) {
            throw new IllegalArgumentException("colour ramp '" + name + "' needs at least one stop");
        }
    }

    /**
     * An interpolating ramp with transparent no-data.
     *
     * @param name the ramp's name, for messages
     * @param stops the stops, at least one
     * @return the ramp
     */
    public static StopRamp of(String name, List<ColorStop> stops) {
        return new StopRamp(name, stops, ColorSelection.INTERPOLATE, Argb.TRANSPARENT);
    }

    /**
     * The same stops with another selection mode.
     *
     * @param newSelection how a colour is picked between stops
     * @return a new ramp; this one is unchanged
     */
    public StopRamp withSelection(ColorSelection newSelection) {
        return new StopRamp(name, stops, newSelection, noDataArgb);
    }

    /**
     * The same stops with another no-data colour (non-premultiplied ARGB).
     *
     * @param argb the colour of no-data cells, 0xAARRGGBB
     * @return a new ramp; this one is unchanged
     */
    public StopRamp withNoDataColor(int argb) {
        return new StopRamp(name, stops, selection, argb);
    }

    /** {@return true when every stop is a percent of the range} */
    public boolean isRelative() {
        return stops.stream().allMatch(s -> s.unit() == StopUnit.PERCENT);
    }

    /** {@return true when every stop is an elevation, so that binding does not depend on the range} */
    public boolean isAbsolute() {
        return stops.stream().allMatch(s -> s.unit() == StopUnit.ABSOLUTE);
    }

    @Override
    public TintFunction bind(ElevationStatistics range) {
        return IntegerLookupTint.over(bindExact(range), range);
    }

    /** The tint without a lookup table (the reference that the table reproduces). */
    TintFunction bindExact(ElevationStatistics range) {
        if (isRelative()) {
            DataRange r = DataRange.of(range);
            return new RatioTint(table(s -> s.level() / 100.0), r);
        }
        if (isAbsolute()) {
            return new ElevationTint(table(ColorStop::level));
        }
        DataRange r = DataRange.of(range);
        return new ElevationTint(table(s -> s.unit() == StopUnit.PERCENT ? r.elevationAt(s.level()) : s.level()));
    }

    private record Placed(double position, int argb) {
    }

    private StopTable table(ToDoubleFunction<ColorStop> placement) {
        List<Placed> placed = new ArrayList<>(stops.size());
        for (ColorStop stop : stops) {
            placed.add(new Placed(placement.applyAsDouble(stop), stop.argb()));
        }
        placed.sort(Comparator.comparingDouble(Placed::position));   // stable: equal positions keep listed order
        double[] positions = new double[placed.size()];
        int[] colours = new int[placed.size()];
        for (int i = 0; i < positions.length; i++) {
            positions[i] = placed.get(i).position();
            colours[i] = placed.get(i).argb();
        }
        return new StopTable(positions, colours, selection, noDataArgb);
    }
}
