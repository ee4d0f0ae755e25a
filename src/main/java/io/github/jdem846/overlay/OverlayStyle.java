package io.github.jdem846.overlay;

import java.awt.Color;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;

/**
 * How an overlay is drawn: line colour and width, polygon fill and point radius.
 *
 * @param stroke      colour of lines, polygon outlines and points (alpha counts)
 * @param width       line width in picture pixels, ≥ 0 (0: polygons are filled only, lines are not drawn)
 * @param fill        colour polygons are filled with (alpha counts), or {@code null} for no fill
 * @param pointRadius radius of the disc drawn for each point, in picture pixels, ≥ 0
 * @param pointColor  colour of the discs drawn for points, or {@code null} for {@code stroke}
 */
public record OverlayStyle(Color stroke, double width, Color fill, double pointRadius, Color pointColor) {

    /** Dark red lines 1.5 px wide, no fill, points of radius 3 px. */
    public static final OverlayStyle DEFAULT = new OverlayStyle(new Color(0xb2, 0x18, 0x2b), 1.5, null, 3);

    private static final Map<String, Color> NAMES = Map.ofEntries(
            Map.entry("black", Color.BLACK), Map.entry("white", Color.WHITE), Map.entry("red", Color.RED),
            Map.entry("green", new Color(0, 128, 0)), Map.entry("blue", Color.BLUE),
            Map.entry("yellow", Color.YELLOW), Map.entry("cyan", Color.CYAN), Map.entry("magenta", Color.MAGENTA),
            Map.entry("orange", Color.ORANGE), Map.entry("gray", Color.GRAY), Map.entry("grey", Color.GRAY));

    /**
     * Checks the sizes.
     *
     * @param stroke      colour of lines, polygon outlines and points (alpha counts)
     * @param width       line width in picture pixels, ≥ 0 (0: polygons are filled only, lines are not drawn)
     * @param fill        colour polygons are filled with (alpha counts), or {@code null} for no fill
     * @param pointRadius radius of the disc drawn for each point, in picture pixels, ≥ 0
     * @param pointColor  colour of the discs drawn for points, or {@code null} for {@code stroke}
     * @throws IllegalArgumentException for a width or radius below 0, NaN or infinite
     */
    public OverlayStyle {
        Objects.requireNonNull(stroke, "stroke");
        if (!(width >= 0) || Double.isInfinite(width) || !(pointRadius >= 0) || Double.isInfinite(pointRadius)) {
            throw new IllegalArgumentException("width and radius must be finite and ≥ 0, got " + width + " and "
                    + pointRadius);
        }
    }

    /**
     * A style whose points take the stroke colour.
     *
     * @param stroke      colour of lines, polygon outlines and points (alpha counts)
     * @param width       line width in picture pixels, ≥ 0 (0: polygons are filled only, lines are not drawn)
     * @param fill        colour polygons are filled with (alpha counts), or {@code null} for no fill
     * @param pointRadius radius of the disc drawn for each point, in picture pixels, ≥ 0
     */
    public OverlayStyle(Color stroke, double width, Color fill, double pointRadius) {
        this(stroke, width, fill, pointRadius, null);
    }

    /** {@return the colour of the discs drawn for points: {@link #pointColor()}, or the stroke colour} */
    public Color pointPaint() {
        return pointColor != null ? pointColor : stroke;
    }

    /**
     * Parses {@code key=value} pairs separated by commas, each changing {@link #DEFAULT}: {@code color} (or
     * {@code stroke}), {@code width}, {@code fill} ({@code none} for none) and {@code radius}. Colours are
     * {@code #RRGGBB}, {@code #RRGGBBAA} or a name (black, white, red, green, blue, yellow, cyan, magenta, orange,
     * gray).
     *
     * @param text the style, e.g. {@code color=#0000ff,width=2,fill=#0000ff40}; empty for the default
     * @return the style
     * @throws IllegalArgumentException when a key or value is not understood; the message says what is allowed
     */
    public static OverlayStyle parse(String text) {
        Color stroke = DEFAULT.stroke;
        double width = DEFAULT.width;
        Color fill = DEFAULT.fill;
        double radius = DEFAULT.pointRadius;
        for (String pair : text.split(",")) {
            if (pair.isBlank()) {
                continue;
            }
            int eq = pair.indexOf('=');
            if (eq < 0) {
                throw new IllegalArgumentException("style item '" + pair + "' is not key=value (keys: color, width,"
                        + " fill, radius)");
            }
            String key = pair.substring(0, eq).strip().toLowerCase(Locale.ROOT);
            String value = pair.substring(eq + 1).strip();
            switch (key) {
                case "color", "colour", "stroke" -> stroke = parseColor(value);
                case "width" -> width = number(key, value);
                case "fill" -> fill = value.equalsIgnoreCase("none") ? null : parseColor(value);
                case "radius" -> radius = number(key, value);
                default -> throw new IllegalArgumentException("unknown style key '" + key
                        + "' (keys: color, width, fill, radius)");
            }
        }
        return new OverlayStyle(stroke, width, fill, radius);
    }

    private static double number(String key, String value) {
        try {
            double v = Double.parseDouble(value);
            if (v >= 0 && Double.isFinite(v)) {
                return v;
            }
        } catch (NumberFormatException e) {
            // reported below
        }
        throw new IllegalArgumentException("style " + key + " '" + value + "' is not a number ≥ 0 (pixels)");
    }

    /** {@return the colour {@code value} names: #RRGGBB, #RRGGBBAA or a name} */
    static Color parseColor(String value) {
        Color named = NAMES.get(value.toLowerCase(Locale.ROOT));
        if (named != null) {
            return named;
        }
        String hex = value.startsWith("#") ? value.substring(1) : "";
        if (hex.matches("[0-9a-fA-F]{6}|[0-9a-fA-F]{8}")) {
            long v = Long.parseLong(hex, 16);
            return hex.length() == 6 ? new Color((int) v)
                    : new Color((int) (v >>> 24), (int) (v >>> 16) & 0xff, (int) (v >>> 8) & 0xff, (int) v & 0xff);
        }
        throw new IllegalArgumentException("colour '" + value + "' is not #RRGGBB, #RRGGBBAA or a colour name ("
                + String.join(", ", new java.util.TreeSet<>(NAMES.keySet())) + ")");
    }
}
