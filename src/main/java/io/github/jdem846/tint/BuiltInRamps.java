package io.github.jdem846.tint;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * The named ramps. Their stops, and where each comes from, are listed in docs/tint.md; the original jDem846's
 * gradient files are described in jdem846-original.md §2.
 */
final class BuiltInRamps {

    /** Primary name → ramp, default first. */
    private static final Map<String, ColorRamp> RAMPS = build();

    /** The original jDem846 identifiers, accepted as aliases. */
    private static final Map<String, String> ALIASES = Map.ofEntries(
            Map.entry("hypsometric-tint", "hypsometric-original"),
            Map.entry("hypsometric-tint-global", "hypsometric-global"),
            Map.entry("hypsometric-tint-natural", "hypsometric-natural"),
            Map.entry("hypsometric-etopo1-tint", "etopo1"),
            Map.entry("bathymetric-tint", "bathymetric"),
            Map.entry("standard-coloring", "standard"),
            Map.entry("gray-tint", "gray"),
            Map.entry("grey", "gray"),
            Map.entry("bumpmap-tint", "bumpmap"),
            Map.entry("dark-bathy-tint", "dark-bathymetric"),
            Map.entry("tri", "tri-green-yellow-red"),
            Map.entry("green-tint", "green"),
            Map.entry("black-tint", "black"));

    private BuiltInRamps() {
    }

    static ColorRamp named(String name) {
        if (name == null) {
            throw new IllegalArgumentException("no colour ramp name given; known ramps: " + String.join(", ", names()));
        }
        String key = name.strip().toLowerCase(Locale.ROOT).replaceAll("[_\\s]+", "-");
        ColorRamp ramp = RAMPS.get(ALIASES.getOrDefault(key, key));
        if (ramp == null) {
            throw new IllegalArgumentException("unknown colour ramp '" + name + "'; known ramps: "
                    + String.join(", ", names()) + " (or give a gdaldem colour file)");
        }
        return ramp;
    }

    static List<String> names() {
        return List.copyOf(RAMPS.keySet());
    }

    private static Map<String, ColorRamp> build() {
        // The article's table 2 (levels in whole percent, colours as printed).
        StopRamp table2 = percent("hypsometric",
                0, 0x006246, 3, 0x248234, 5, 0xE4CF7E, 18, 0x9A4600,
                39, 0x7C2123, 52, 0x797979, 68, 0xB2B2B2, 100, 0xE5E5E5);
        // The original's gradient/bathymetric.json.
        StopRamp bathymetric = percent("bathymetric",
                2.5, rgb(24, 23, 54), 6.25, rgb(21, 46, 103), 12.5, rgb(21, 87, 135), 25, rgb(21, 138, 171),
                37.5, rgb(27, 155, 184), 50, rgb(11, 176, 203), 62.5, rgb(55, 186, 216), 75, rgb(95, 194, 217),
                87.5, rgb(134, 205, 211), 100, rgb(175, 218, 209));
        // The original's gradient/hypsometric-global.json (table 2 is this, rounded).
        StopRamp global = percent("hypsometric-global",
                0, rgb(0, 99, 70), 3.2967, rgb(37, 131, 53), 5.3407, rgb(228, 207, 126), 18.0769, rgb(154, 70, 0),
                39.3626, rgb(124, 34, 36), 51.6484, rgb(121, 121, 121), 68.1319, rgb(179, 179, 179),
                100, rgb(230, 230, 230));

        Map<String, ColorRamp> m = new LinkedHashMap<>();
        // The default: table 2, split at 0 m with bathymetric below when the DEM holds land and sea.
        add(m, new TopoBathyRamp(ColorRamp.DEFAULT_NAME, table2, bathymetric));
        add(m, table2);
        // The original's gradient/hypsometric.json.
        add(m, percent("hypsometric-original",
                0, rgb(0, 99, 70), 17.9381, rgb(37, 131, 53), 30.1031, rgb(228, 207, 126), 40, rgb(154, 70, 0),
                55.0515, rgb(124, 34, 36), 77.9381, rgb(121, 121, 121), 92.9897, rgb(179, 179, 179),
                100, rgb(230, 230, 230)));
        add(m, global);
        // The original's gradient/hypsometric-natural.json.
        add(m, percent("hypsometric-natural",
                0, rgb(187, 170, 102), 7.7519, rgb(153, 102, 51), 14.3411, rgb(89, 120, 52),
                31.7829, rgb(102, 102, 51), 68.6046, rgb(68, 68, 51), 100, rgb(195, 195, 195)));
        add(m, bathymetric);
        add(m, etopo1());
        // The original's default (StandardModelColoring): global above 0 m, bathymetric at and below.
        add(m, new SeaLandRamp("standard", global, bathymetric));
        // The original's gray-tint: one colour, (0.5, 0.5, 0.5).
        add(m, percent("gray", 0, rgb(128, 128, 128)));
        // The original's bumpmap: black at the minimum to white at the maximum.
        add(m, percent("bumpmap", 0, rgb(0, 0, 0), 100, rgb(255, 255, 255)));
        // The original's gradient/dark-bathymetric.json: dark blues in metres below sea level, white land.
        add(m, StopRamp.of("dark-bathymetric", List.of(
                ColorStop.absolute(-11000, 3, 8, 16), ColorStop.absolute(-500, 26, 71, 128),
                ColorStop.absolute(-0.001, 26, 71, 128), ColorStop.absolute(-0.001, 255, 255, 255),
                ColorStop.absolute(8500, 255, 255, 255))));
        // The original's gradient/tri.json (its terrain-ruggedness colourer's ramp).
        add(m, percent("tri-green-yellow-red", 0, rgb(0, 255, 0), 50, rgb(255, 255, 0), 100, rgb(255, 0, 0)));
        // The original's GreenTint, BlackTint and TransparentColoring: one colour each.
        add(m, percent("green", 0, rgb(146, 173, 144)));
        add(m, percent("black", 0, rgb(0, 0, 0)));
        add(m, StopRamp.of("transparent", List.of(new ColorStop(0, StopUnit.PERCENT, 0))));
        return Collections.unmodifiableMap(m);
    }

    /**
     * ETOPO1's palette (NOAA NGDC; sea colours after GMT_haxby, land after GMT_globe), in metres, with the hard
     * step at −0.001 m: 43 stops as in the original's hypsometric-etopo1.json. Transcribed from cpt-city
     * {@code ngdc/tn/ETOPO1}, as redistributed in github.com/jiho/chroma {@code data-raw/ETOPO1.pg}.
     */
    private static StopRamp etopo1() {
        int[][] sea = {
            {-11000, 10, 0, 121}, {-10500, 26, 0, 137}, {-10000, 38, 0, 152}, {-9500, 27, 3, 166},
            {-9000, 16, 6, 180}, {-8500, 5, 9, 193}, {-8000, 0, 14, 203}, {-7500, 0, 22, 210},
            {-7000, 0, 30, 216}, {-6500, 0, 39, 223}, {-6000, 12, 68, 231}, {-5500, 26, 102, 240},
            {-5000, 19, 117, 244}, {-4500, 14, 133, 249}, {-4000, 21, 158, 252}, {-3500, 30, 178, 255},
            {-3000, 43, 186, 255}, {-2500, 55, 193, 255}, {-2000, 65, 200, 255}, {-1500, 79, 210, 255},
            {-1000, 94, 223, 255}, {-500, 138, 227, 255},
        };
        int[][] land = {
            {100, 51, 204, 102}, {200, 187, 228, 146}, {500, 255, 220, 185}, {1000, 243, 202, 137},
            {1500, 230, 184, 88}, {2000, 217, 166, 39}, {2500, 168, 154, 31}, {3000, 164, 144, 25},
            {3500, 162, 134, 19}, {4000, 159, 123, 13}, {4500, 156, 113, 7}, {5000, 153, 102, 0},
            {5500, 162, 89, 89}, {6000, 178, 118, 118}, {6500, 183, 147, 147}, {7000, 194, 176, 176},
            {7500, 204, 204, 204}, {8000, 229, 229, 229}, {8500, 255, 255, 255},
        };
        List<ColorStop> stops = new ArrayList<>();
        for (int[] s : sea) {
            stops.add(ColorStop.absolute(s[0], s[1], s[2], s[3]));
        }
        stops.add(ColorStop.absolute(-0.001, 188, 230, 255));   // last sea colour ...
        stops.add(ColorStop.absolute(-0.001, 51, 102, 0));      // ... and the step to the first land colour
        for (int[] s : land) {
            stops.add(ColorStop.absolute(s[0], s[1], s[2], s[3]));
        }
        return StopRamp.of("etopo1", stops);
    }

    private static void add(Map<String, ColorRamp> m, ColorRamp ramp) {
        m.put(ramp.name(), ramp);
    }

    private static int rgb(int r, int g, int b) {
        return r << 16 | g << 8 | b;
    }

    /** A percent ramp from pairs (percent, 0xRRGGBB). */
    private static StopRamp percent(String name, double... levelAndRgb) {
        List<ColorStop> stops = new ArrayList<>();
        for (int i = 0; i < levelAndRgb.length; i += 2) {
            int c = (int) levelAndRgb[i + 1];
            stops.add(ColorStop.percent(levelAndRgb[i], Argb.red(c), Argb.green(c), Argb.blue(c)));
        }
        return StopRamp.of(name, stops);
    }
}
