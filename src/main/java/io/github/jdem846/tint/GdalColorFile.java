package io.github.jdem846.tint;

import java.io.BufferedReader;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Pattern;

/**
 * Reader of the colour files of {@code gdaldem color-relief}, following GDAL's parser (apps/gdaldem_lib.cpp,
 * {@code GDALColorReliefParseColorFile}; {@code GDALLoadTextColorMap} in recent GDAL) line by line:
 * <ul>
 *   <li>fields are split at any run of spaces, tabs, commas and colons;</li>
 *   <li>a line whose first field starts with {@code #} or {@code /} is a comment, a blank line is skipped;</li>
 *   <li>the first field is an elevation, {@code N%} (0–100) of the DEM's range, or {@code nv} (the no-data
 *       colour, any case);</li>
 *   <li>then {@code R G B [A]} (integers 0–255) or a colour name and an optional alpha; fields after the alpha
 *       are ignored, as gdaldem ignores them;</li>
 *   <li>a comment line containing {@code COLOR_MODEL = RGB} switches to GMT {@code .cpt} lines
 *       {@code z0 R0 G0 B0 z1 R1 G1 B1} and {@code B|F|N R G B} (only N, the no-data colour, is used).</li>
 * </ul>
 * Where gdaldem silently reads garbage (a non-number read as 0 by {@code atof}, a channel above 255 wrapping), this
 * reader stops with the file, the line number and what would be right.
 */
final class GdalColorFile {

    /** gdaldem's named colours: {@code (int) (255.0 · fraction)} of GRASS's table, hence 191 and 127. */
    static final Map<String, Integer> NAMED_COLOURS = namedColours();

    private static final Pattern SEPARATORS = Pattern.compile("[ ,\t:]+");
    private static final Pattern NUMBER = Pattern.compile("[+-]?(\\d+\\.?\\d*|\\.\\d+)([eE][+-]?\\d+)?");
    private static final Pattern INTEGER = Pattern.compile("[+-]?\\d+");
    private static final String UTF8_BOM_AS_LATIN1 = "\u00EF\u00BB\u00BF";

    private GdalColorFile() {
    }

    static StopRamp read(Path file, ColorSelection selection) throws IOException {
        List<String> lines = new ArrayList<>();
        // Latin-1 never fails to decode; everything gdaldem understands is ASCII.
        try (BufferedReader in = Files.newBufferedReader(file, StandardCharsets.ISO_8859_1)) {
            for (String line = in.readLine(); line != null; line = in.readLine()) {
                lines.add(line);
            }
        }
        Path name = file.getFileName();
        return parse(lines, file.toString(), name == null ? file.toString() : name.toString(), selection);
    }

    /**
     * @param source    how messages name the file
     * @param rampName  the ramp's name
     */
    static StopRamp parse(List<String> lines, String source, String rampName, ColorSelection selection)
            throws ColorFileException {
        List<ColorStop> stops = new ArrayList<>();
        Integer noData = null;
        int noDataLine = 0;
        boolean cpt = false;
        for (int n = 1; n <= lines.size(); n++) {
            String line = lines.get(n - 1);
            if (n == 1 && line.startsWith(UTF8_BOM_AS_LATIN1)) {
                line = line.substring(UTF8_BOM_AS_LATIN1.length());
            }
            if (line.startsWith("#") && line.contains("COLOR_MODEL")) {
                if (!line.contains("COLOR_MODEL = RGB")) {
                    throw new ColorFileException(source, n, "only '# COLOR_MODEL = RGB' GMT palettes are supported "
                            + "(as in gdaldem), got '" + line.strip() + "'");
                }
                cpt = true;
            }
            String[] f = fields(line);
            if (f.length == 0 || f[0].startsWith("#") || f[0].startsWith("/")) {
                continue;
            }
            Line at = new Line(source, n, line);
            if (cpt) {
                if (f.length == 8) {
                    stops.add(new ColorStop(at.number(f[0], "z0"), StopUnit.ABSOLUTE, at.rgb(f, 1, null)));
                    stops.add(new ColorStop(at.number(f[4], "z1"), StopUnit.ABSOLUTE, at.rgb(f, 5, null)));
                } else if (f.length == 4 && f[0].length() == 1 && "BFNbfn".contains(f[0])) {
                    int argb = at.rgb(f, 1, null);
                    if (f[0].equalsIgnoreCase("N")) {
                        if (noData != null) {
                            throw at.error("the no-data colour is given twice (also on line " + noDataLine + ")");
                        }
                        noData = argb;
                        noDataLine = n;
                    }
                } else {
                    throw at.error("a GMT palette line needs 8 fields 'z0 R G B z1 R G B' or 4 fields 'B|F|N R G B', "
                            + "got " + f.length);
                }
                continue;
            }
            if (f.length < 2) {
                throw at.error("expected 'value R G B [A]' or 'value colourname [A]', got only '" + f[0] + "'");
            }
            int argb = f.length >= 4 ? at.rgb(f, 1, f.length >= 5 ? f[4] : null) : at.named(f[1],
                    f.length == 3 ? f[2] : null);
            String value = f[0];
            if (value.equalsIgnoreCase("nv")) {
                if (noData != null) {
                    throw at.error("'nv' (the no-data colour) is given twice (also on line " + noDataLine + ")");
                }
                noData = argb;
                noDataLine = n;
            } else if (value.length() > 1 && value.endsWith("%")) {
                double percent = at.number(value.substring(0, value.length() - 1), "percentage");
                if (percent < 0 || percent > 100) {
                    throw at.error("a percentage must lie between 0% and 100%, got " + value);
                }
                stops.add(new ColorStop(percent, StopUnit.PERCENT, argb));
            } else {
                stops.add(new ColorStop(at.number(value, "elevation"), StopUnit.ABSOLUTE, argb));
            }
        }
        if (stops.isEmpty()) {
            throw new ColorFileException(source, "no colour entries; expected lines such as '1000 255 128 0' "
                    + "(elevation R G B [A]), '50% white' or 'nv 0 0 0 0'");
        }
        return new StopRamp(rampName, stops, selection, noData == null ? Argb.TRANSPARENT : noData);
    }

    static String[] fields(String line) {
        String s = line.strip();
        return s.isEmpty() ? new String[0] : SEPARATORS.split(s.replaceFirst("^[ ,\t:]+", ""));
    }

    /** One line being parsed, for messages. */
    private record Line(String source, int number, String text) {

        ColorFileException error(String problem) {
            return new ColorFileException(source, number, problem + " in '" + text.strip() + "'");
        }

        double number(String field, String what) throws ColorFileException {
            if (!NUMBER.matcher(field).matches()) {
                throw error("the " + what + " '" + field + "' is not a number");
            }
            double v = Double.parseDouble(field);
            if (!Double.isFinite(v)) {
                throw error("the " + what + " '" + field + "' is out of range");
            }
            return v;
        }

        int channel(String field, String what) throws ColorFileException {
            if (!INTEGER.matcher(field).matches()) {
                String hint = field.startsWith("#") ? " (gdaldem would read it as 0; put comments on their own line)"
                        : "";
                throw error("the " + what + " '" + field + "' is not an integer 0–255" + hint);
            }
            long v = field.length() > 12 ? Long.MAX_VALUE : Long.parseLong(field);
            if (v < 0 || v > 255) {
                throw error("the " + what + " must lie between 0 and 255, got " + field);
            }
            return (int) v;
        }

        /** R G B at {@code f[from..from+2]}, alpha from {@code alpha} or opaque. */
        int rgb(String[] f, int from, String alpha) throws ColorFileException {
            int r = channel(f[from], "red");
            int g = channel(f[from + 1], "green");
            int b = channel(f[from + 2], "blue");
            int a = alpha == null ? 255 : channel(alpha, "alpha");
            return Argb.of(r, g, b, a);
        }

        int named(String name, String alpha) throws ColorFileException {
            Integer rgb = NAMED_COLOURS.get(name.toLowerCase(Locale.ROOT));
            if (rgb == null) {
                if (INTEGER.matcher(name).matches() || NUMBER.matcher(name).matches()) {
                    throw error("expected 'value R G B [A]' (three colour components) or 'value colourname [A]'");
                }
                throw error("unknown colour name '" + name + "'; gdaldem knows " + String.join(", ",
                        NAMED_COLOURS.keySet()) + ", or give 'R G B [A]'");
            }
            int a = alpha == null ? 255 : channel(alpha, "alpha");
            return Argb.of(Argb.red(rgb), Argb.green(rgb), Argb.blue(rgb), a);
        }
    }

    private static Map<String, Integer> namedColours() {
        String[] names = {"white", "black", "red", "green", "blue", "yellow", "magenta", "cyan", "aqua", "grey", "gray",
            "orange", "brown", "purple", "violet", "indigo"};
        double[][] fractions = {{1, 1, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, 0, 1},
            {0, 1, 1}, {0, .75, .75}, {.75, .75, .75}, {.75, .75, .75}, {1, .5, 0}, {.75, .5, .25}, {.5, 0, 1},
            {.5, 0, 1}, {0, .5, 1}};
        Map<String, Integer> m = new LinkedHashMap<>();
        for (int i = 0; i < names.length; i++) {
            double[] c = fractions[i];
            m.put(names[i], (int) (255.0 * c[0]) << 16 | (int) (255.0 * c[1]) << 8 | (int) (255.0 * c[2]));
        }
        return Collections.unmodifiableMap(m);
    }
}
