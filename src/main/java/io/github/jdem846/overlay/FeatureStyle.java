package io.github.jdem846.overlay;

import java.awt.Color;
import java.util.Locale;
import java.util.Map;

/**
 * The style one feature gives itself with the <a href="https://github.com/mapbox/simplestyle-spec">simplestyle-spec
 * 1.1</a> properties, each overriding the file's {@link OverlayStyle} for that feature: {@code stroke},
 * {@code stroke-width}, {@code stroke-opacity}, {@code fill}, {@code fill-opacity}, {@code marker-color} and
 * {@code marker-size} (a shapefile's {@code .dbf} may hold them under the 10-character names {@code ogr2ogr} cuts
 * them to: {@code stroke-wid}, {@code stroke-opa}, {@code fill-opaci}, {@code marker-col}, {@code marker-siz}).
 * Other properties are ignored; an empty or null value is as if the property were not there.
 *
 * @param stroke        colour of lines and outlines (opaque), or null to keep the file's
 * @param strokeWidth   line width in picture pixels, or NaN to keep the file's
 * @param strokeOpacity alpha of lines and outlines, 0 to 1, or NaN to keep the file's colour's
 * @param fill          colour of polygon fills (opaque), or null to keep the file's
 * @param fillOpacity   alpha of polygon fills, 0 to 1, or NaN: the file's fill's alpha, or 0.6 when the file has no
 *                      fill (simplestyle's default)
 * @param markerColor   colour of point discs (opaque), or null: points take the stroke colour
 * @param markerRadius  radius of point discs in picture pixels ({@code marker-size} small 2, medium 3, large 5, or a
 *                      number of pixels), or NaN to keep the file's
 */
public record FeatureStyle(Color stroke, double strokeWidth, double strokeOpacity, Color fill, double fillOpacity,
                           Color markerColor, double markerRadius) {

    /** A feature without style properties: the file's style applies unchanged. */
    public static final FeatureStyle NONE = new FeatureStyle(null, Double.NaN, Double.NaN, null, Double.NaN, null,
            Double.NaN);

    /** simplestyle's default fill opacity, used for a feature's fill when neither it nor the file gives one. */
    public static final double DEFAULT_FILL_OPACITY = 0.6;

    private static final Map<String, String> SHORT_NAMES = Map.of("stroke-wid", "stroke-width",
            "stroke-opa", "stroke-opacity", "fill-opaci", "fill-opacity", "marker-col", "marker-color",
            "marker-siz", "marker-size");

    /**
     * Checks the numbers.
     *
     * @param stroke        colour of lines and outlines (opaque), or null to keep the file's
     * @param strokeWidth   line width in picture pixels, or NaN to keep the file's
     * @param strokeOpacity alpha of lines and outlines, 0 to 1, or NaN to keep the file's colour's
     * @param fill          colour of polygon fills (opaque), or null to keep the file's
     * @param fillOpacity   alpha of polygon fills, 0 to 1, or NaN (see the record's description)
     * @param markerColor   colour of point discs (opaque), or null: points take the stroke colour
     * @param markerRadius  radius of point discs in picture pixels, or NaN to keep the file's
     * @throws IllegalArgumentException for a width or radius below 0 or infinite, an opacity outside 0 to 1
     */
    public FeatureStyle {
        if (strokeWidth < 0 || Double.isInfinite(strokeWidth) || markerRadius < 0 || Double.isInfinite(markerRadius)
                || strokeOpacity < 0 || strokeOpacity > 1 || fillOpacity < 0 || fillOpacity > 1) {
            throw new IllegalArgumentException("widths and radii must be finite and ≥ 0, opacities 0 to 1");
        }
    }

    /**
     * The style of a feature's properties (GeoJSON {@code properties} or a {@code .dbf} record).
     *
     * @param properties names to values (strings or numbers); may be null
     * @return the style, {@link #NONE} when no style property is there
     * @throws IllegalArgumentException when a style property's value is not understood; the message names it and says
     *                                  what is allowed
     */
    public static FeatureStyle of(Map<String, ?> properties) {
        if (properties == null || properties.isEmpty()) {
            return NONE;
        }
        Color stroke = null;
        double width = Double.NaN;
        double strokeOpacity = Double.NaN;
        Color fill = null;
        double fillOpacity = Double.NaN;
        Color marker = null;
        double radius = Double.NaN;
        for (Map.Entry<String, ?> e : properties.entrySet()) {
            if (e.getKey() == null || e.getValue() == null || e.getValue().toString().isBlank()) {
                continue;
            }
            String key = e.getKey().strip().toLowerCase(Locale.ROOT);
            key = SHORT_NAMES.getOrDefault(key, key);
            Object value = e.getValue();
            switch (key) {
                case "stroke" -> stroke = opaque(key, value);
                case "stroke-width" -> width = number(key, value, Double.POSITIVE_INFINITY);
                case "stroke-opacity" -> strokeOpacity = number(key, value, 1);
                case "fill" -> fill = opaque(key, value);
                case "fill-opacity" -> fillOpacity = number(key, value, 1);
                case "marker-color" -> marker = opaque(key, value);
                case "marker-size" -> radius = markerRadius(value);
                default -> {
                    // not a style property
                }
            }
        }
        FeatureStyle s = new FeatureStyle(stroke, width, strokeOpacity, fill, fillOpacity, marker, radius);
        return s.equals(NONE) ? NONE : s;
    }

    /**
     * The style a feature is drawn with.
     *
     * @param file the file's style
     * @return {@code file} with this feature's properties put over it
     */
    public OverlayStyle over(OverlayStyle file) {
        if (this.equals(NONE)) {
            return file;
        }
        Color s = stroke != null ? stroke : file.stroke();
        int strokeAlpha = Double.isNaN(strokeOpacity) ? file.stroke().getAlpha() : alpha(strokeOpacity);
        Color strokeColor = withAlpha(s, strokeAlpha);
        Color fillColor = file.fill();
        if (fill != null || (!Double.isNaN(fillOpacity) && file.fill() != null)) {
            Color f = fill != null ? fill : file.fill();
            int a = !Double.isNaN(fillOpacity) ? alpha(fillOpacity)
                    : file.fill() != null ? file.fill().getAlpha() : alpha(DEFAULT_FILL_OPACITY);
            fillColor = withAlpha(f, a);
        }
        double width = Double.isNaN(strokeWidth) ? file.width() : strokeWidth;
        double radius = Double.isNaN(markerRadius) ? file.pointRadius() : markerRadius;
        Color point = markerColor != null ? withAlpha(markerColor, strokeAlpha) : null;
        return new OverlayStyle(strokeColor, width, fillColor, radius, point);
    }

    private static int alpha(double opacity) {
        return (int) Math.round(opacity * 255);
    }

    private static Color withAlpha(Color c, int alpha) {
        return new Color(c.getRed(), c.getGreen(), c.getBlue(), alpha);
    }

    private static Color opaque(String key, Object value) {
        String text = value.toString().strip();
        if (text.matches("#[0-9a-fA-F]{3}")) {
            text = "#" + text.charAt(1) + text.charAt(1) + text.charAt(2) + text.charAt(2) + text.charAt(3)
                    + text.charAt(3);
        }
        try {
            return OverlayStyle.parseColor(text);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("property " + key + ": " + e.getMessage()
                    .replace("is not #RRGGBB", "is not #RGB, #RRGGBB"));
        }
    }

    private static double number(String key, Object value, double max) {
        double v = Double.NaN;
        if (value instanceof Number n) {
            v = n.doubleValue();
        } else {
            try {
                v = Double.parseDouble(value.toString().strip());
            } catch (NumberFormatException e) {
                // reported below
            }
        }
        if (v >= 0 && v <= max && Double.isFinite(v)) {
            return v;
        }
        throw new IllegalArgumentException("property " + key + " '" + value + "' is not a number "
                + (max == 1 ? "from 0 to 1" : "≥ 0 (pixels)"));
    }

    private static double markerRadius(Object value) {
        String text = value.toString().strip().toLowerCase(Locale.ROOT);
        return switch (text) {
            case "small" -> 2;
            case "medium" -> 3;
            case "large" -> 5;
            default -> {
                try {
                    yield number("marker-size", value, Double.POSITIVE_INFINITY);
                } catch (IllegalArgumentException e) {
                    throw new IllegalArgumentException("property marker-size '" + value + "' is not small, medium, "
                            + "large or a radius in pixels");
                }
            }
        };
    }
}
