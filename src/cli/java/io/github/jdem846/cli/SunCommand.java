package io.github.jdem846.cli;

import io.github.jdem846.geo.LatLon;
import io.github.jdem846.sun.Observer;
import io.github.jdem846.sun.SolarCalculator;
import io.github.jdem846.sun.SunAtInstant;
import io.github.jdem846.sun.SunEvents;
import io.github.jdem846.sun.SunPosition;
import io.github.jdem846.sun.ZonedTimeParser;
import java.io.PrintWriter;
import java.time.ZoneOffset;
import java.time.ZonedDateTime;
import java.time.format.DateTimeFormatter;
import java.time.temporal.ChronoUnit;
import java.util.Locale;
import java.util.Optional;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code jdem846 sun}: the sun's azimuth, elevation and zenith angle for a time and place, with the day's sunrise,
 * transit and sunset (NREL SPA). Text for a person, or {@code --json}.
 */
@Command(name = "sun", addMethodSubcommands = false,
        mixinStandardHelpOptions = true,
        sortOptions = false,
        description = {
            "Where the sun is at a time and place (NREL SPA, refraction included), and the day's sunrise, transit "
                    + "and sunset in the time's own zone.",
            "Azimuth is clockwise from north; elevation = 90 - zenith, negative at night."},
        footer = {"", "Examples:",
            "  jdem846 sun --time 2003-10-17T12:30:30-07:00 --at 39.742476,-105.1786 --height 1830.14 "
                    + "--pressure 820 --temperature 11 --delta-t 67",
            "  jdem846 sun --time 2024-06-21T05:00[Europe/Luxembourg] --at 49.61,6.13 --json"})
public final class SunCommand implements Callable<Integer> {

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Option(names = "--time", required = true, paramLabel = "T", converter = TimeConverter.class,
            description = "ISO-8601 time with a UTC offset or a zone: 2003-10-17T12:30:30-07:00, "
                    + "2024-06-21T03:00Z, 2024-06-21T05:00[Europe/Luxembourg].")
    ZonedDateTime time;

    @Option(names = "--at", required = true, paramLabel = "LAT,LON", converter = LatLonConverter.class,
            description = "Latitude and longitude in decimal degrees, north and east positive, e.g. 49.61,6.13 "
                    + "or -33.92,18.42.")
    LatLon at;

    @Option(names = "--height", paramLabel = "M", defaultValue = "0", converter = Converters.ObserverHeight.class,
            description = "Height above sea level in metres, -500 to 20000 (default: ${DEFAULT-VALUE}).")
    double heightMeters;

    @Option(names = "--pressure", paramLabel = "MBAR", converter = Converters.Pressure.class,
            description = "Mean air pressure in millibars for refraction, above 0 and at most 2000 (default: "
                    + "standard atmosphere at the height, 1013.25 at sea level).")
    Double pressure;

    @Option(names = "--temperature", paramLabel = "C", converter = Converters.Temperature.class,
            description = "Mean air temperature in °C for refraction, -100 to 100 (default: standard atmosphere at "
                    + "the height, 15 at sea level).")
    Double temperature;

    @Option(names = "--delta-t", paramLabel = "S", converter = Converters.DeltaT.class,
            description = "Delta T = TT - UT in seconds, within ±200000 (default: the estimate for the date, about "
                    + "71 s in 2024).")
    Double deltaT;

    @Mixin
    BodyOptions bodyOptions;

    @Option(names = "--json", description = "Print one JSON object instead of text.")
    boolean json;

    @Mixin
    VerboseOption verbose;

    @Override
    public Integer call() {
        bodyOptions.bodyForSunByTime();
        Observer observer = observer();
        SunAtInstant sun = SunAtInstant.of(time, observer);
        SunPosition position = sun.position(at);
        SunEvents events = SolarCalculator.events(time, at, observer);
        PrintWriter out = spec.commandLine().getOut();
        out.print(json ? json(sun, position, events) : text(sun, position, events));
        out.flush();
        return 0;
    }

    /** The observer of the options, each of which was checked as it was parsed. */
    private Observer observer() {
        Observer o = Observer.atHeight(heightMeters);
        if (pressure != null) {
            o = o.withPressure(pressure);
        }
        if (temperature != null) {
            o = o.withTemperature(temperature);
        }
        if (deltaT != null) {
            o = o.withDeltaT(deltaT);
        }
        return o;
    }

    private String text(SunAtInstant sun, SunPosition p, SunEvents e) {
        Observer o = sun.observer();
        StringBuilder sb = new StringBuilder();
        line(sb, "time", format(time));
        line(sb, "place", at + String.format(Locale.ROOT, ", %.2f m", o.heightMeters()));
        line(sb, "azimuth", String.format(Locale.ROOT, "%.5f° (clockwise from north)", p.azimuthDegrees()));
        line(sb, "elevation", String.format(Locale.ROOT, "%.5f°%s", p.elevationDegrees(),
                p.isBelowHorizon() ? " (below the horizon: no direct light)" : ""));
        line(sb, "zenith", String.format(Locale.ROOT, "%.5f°", p.zenithDegrees()));
        String none = switch (e.kind()) {
            case POLAR_DAY -> "none (polar day: the sun stays above the horizon all day)";
            case POLAR_NIGHT -> "none (polar night: the sun stays below the horizon all day)";
            case REGULAR -> "";
        };
        line(sb, "sunrise", e.sunrise().map(SunCommand::format).orElse(none));
        line(sb, "transit", format(e.transit()));
        line(sb, "sunset", e.sunset().map(SunCommand::format).orElse(none));
        line(sb, "air", String.format(Locale.ROOT, "%.1f mbar, %.1f °C", o.pressureMillibars(),
                o.temperatureCelsius()));
        line(sb, "delta T", String.format(Locale.ROOT, "%.2f s (%s)", sun.deltaTSeconds(),
                o.isDeltaTEstimated() ? "estimated for the date" : "given"));
        return sb.toString();
    }

    private static void line(StringBuilder sb, String key, String value) {
        sb.append(String.format(Locale.ROOT, "%-10s %s%n", key, value));
    }

    private String json(SunAtInstant sun, SunPosition p, SunEvents e) {
        Observer o = sun.observer();
        StringBuilder sb = new StringBuilder("{");
        field(sb, "time", quote(format(time)));
        field(sb, "latitude", number(at.latitude()));
        field(sb, "longitude", number(at.longitude()));
        field(sb, "height", number(o.heightMeters()));
        field(sb, "azimuth", number(p.azimuthDegrees()));
        field(sb, "elevation", number(p.elevationDegrees()));
        field(sb, "zenith", number(p.zenithDegrees()));
        field(sb, "belowHorizon", Boolean.toString(p.isBelowHorizon()));
        field(sb, "sunrise", optional(e.sunrise()));
        field(sb, "transit", quote(format(e.transit())));
        field(sb, "sunset", optional(e.sunset()));
        field(sb, "day", quote(e.kind().name().toLowerCase(Locale.ROOT)));
        field(sb, "pressure", number(o.pressureMillibars()));
        field(sb, "temperature", number(o.temperatureCelsius()));
        field(sb, "deltaT", number(sun.deltaTSeconds()));
        field(sb, "deltaTEstimated", Boolean.toString(o.isDeltaTEstimated()));
        sb.setLength(sb.length() - 1);
        return sb.append("}").append(System.lineSeparator()).toString();
    }

    private static void field(StringBuilder sb, String key, String value) {
        sb.append('"').append(key).append("\":").append(value).append(',');
    }

    private static String optional(Optional<ZonedDateTime> t) {
        return t.map(SunCommand::format).map(SunCommand::quote).orElse("null");
    }

    private static String number(double v) {
        return String.format(Locale.ROOT, "%.6f", v);
    }

    private static String quote(String s) {
        return '"' + s.replace("\\", "\\\\").replace("\"", "\\\"") + '"';
    }

    /** ISO-8601 to the second, with the offset, and the zone id in brackets when the time was given with one. */
    static String format(ZonedDateTime t) {
        ZonedDateTime s = t.truncatedTo(ChronoUnit.SECONDS);
        return s.getZone() instanceof ZoneOffset ? DateTimeFormatter.ISO_OFFSET_DATE_TIME.format(s)
                : DateTimeFormatter.ISO_ZONED_DATE_TIME.format(s);
    }

    /** Reads {@code --time}. */
    static final class TimeConverter implements CommandLine.ITypeConverter<ZonedDateTime> {
        @Override
        public ZonedDateTime convert(String value) {
            return Converters.checked(() -> ZonedTimeParser.parse(value));
        }
    }

    /** Reads {@code --at}. */
    static final class LatLonConverter implements CommandLine.ITypeConverter<LatLon> {
        @Override
        public LatLon convert(String value) {
            return Converters.checked(() -> LatLon.parse(value));
        }
    }
}
