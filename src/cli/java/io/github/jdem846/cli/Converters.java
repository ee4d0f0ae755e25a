package io.github.jdem846.cli;

import io.github.jdem846.io.Window;
import io.github.jdem846.light.LightDirection;
import io.github.jdem846.render.OutputSize;
import io.github.jdem846.render.RenderSettings;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shade.HillshadeMethod;
import io.github.jdem846.shade.HillshadeOptions;
import io.github.jdem846.shadow.ShadowAlgorithm;
import io.github.jdem846.shadow.ShadowOptions;
import io.github.jdem846.sun.Body;
import io.github.jdem846.sun.Observer;
import io.github.jdem846.sun.ZonedTimeParser;
import java.util.Locale;
import java.util.function.DoubleConsumer;
import java.util.function.IntConsumer;
import java.util.function.Supplier;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/**
 * Option values checked as they are parsed: each converter reads the text and runs the check of the library class
 * the value is for, which holds the range. A failure is picocli's "Invalid value for option '--x': …", one line
 * and exit status 2 ({@link CliExceptionHandler}).
 */
final class Converters {

    private Converters() {
    }

    /** {@code check}'s IllegalArgumentException as a conversion failure with its message. */
    static <T> T checked(Supplier<T> check) {
        try {
            return check.get();
        } catch (IllegalArgumentException e) {
            throw new TypeConversionException(e.getMessage());
        }
    }

    /** {@code text} as a double (NaN and Infinity are numbers here), checked by {@code check}. */
    static double checkedDouble(String text, DoubleConsumer check) {
        double v;
        try {
            v = Double.parseDouble(text.trim());
        } catch (NumberFormatException e) {
            throw new TypeConversionException("'" + text + "' is not a number");
        }
        return checked(() -> {
            check.accept(v);
            return v;
        });
    }

    /** {@code text} as an int, checked by {@code check}. */
    static int checkedInt(String text, IntConsumer check) {
        int v;
        try {
            v = Integer.parseInt(text.trim());
        } catch (NumberFormatException e) {
            throw new TypeConversionException("'" + text + "' is not a whole number within ±2147483647");
        }
        return checked(() -> {
            check.accept(v);
            return v;
        });
    }

    /** {@code --width}: {@link OutputSize#width(int)}. */
    static final class Width implements ITypeConverter<Integer> {
        @Override
        public Integer convert(String text) {
            return checkedInt(text, OutputSize::width);
        }
    }

    /** {@code --height}: {@link OutputSize#height(int)}. */
    static final class Height implements ITypeConverter<Integer> {
        @Override
        public Integer convert(String text) {
            return checkedInt(text, OutputSize::height);
        }
    }

    /** {@code --scale}: {@link OutputSize#scale(double)}. */
    static final class Scale implements ITypeConverter<Double> {
        @Override
        public Double convert(String text) {
            return checkedDouble(text, OutputSize::scale);
        }
    }

    /** {@code --window W,S,E,N} or {@code cells:COL,ROW,W,H}: {@link Window#world} or {@link Window#cells}. */
    static final class WindowValue implements ITypeConverter<Window> {
        @Override
        public Window convert(String text) {
            String t = text.trim();
            boolean cells = t.toLowerCase(Locale.ROOT).startsWith("cells:");
            String[] parts = (cells ? t.substring(6) : t).split(",", -1);
            String expected = "'" + text + "' is not a window: expected WEST,SOUTH,EAST,NORTH in the DEM's CRS units"
                    + " or cells:COL,ROW,WIDTH,HEIGHT";
            if (parts.length != 4) {
                throw new TypeConversionException(expected);
            }
            double[] v = new double[4];
            try {
                for (int i = 0; i < 4; i++) {
                    v[i] = cells ? Integer.parseInt(parts[i].trim()) : Double.parseDouble(parts[i].trim());
                }
            } catch (NumberFormatException e) {
                throw new TypeConversionException(expected);
            }
            return checked(() -> cells ? Window.cells((int) v[0], (int) v[1], (int) v[2], (int) v[3])
                    : Window.world(v[0], v[1], v[2], v[3]));
        }
    }

    /** {@code --threads}: {@link RenderSettings}. */
    static final class Threads implements ITypeConverter<Integer> {
        @Override
        public Integer convert(String text) {
            return checkedInt(text, n -> new RenderSettings(n, RenderSettings.DEFAULT_TILE_SIZE));
        }
    }

    /** {@code --tile-size}: {@link RenderSettings}. */
    static final class TileSize implements ITypeConverter<Integer> {
        @Override
        public Integer convert(String text) {
            return checkedInt(text, n -> new RenderSettings(1, n));
        }
    }

    /** {@code --z-factor}: {@link HillshadeOptions}. */
    static final class ZFactor implements ITypeConverter<Double> {
        @Override
        public Double convert(String text) {
            return checkedDouble(text, HillshadeOptions.DEFAULTS::withZFactor);
        }
    }

    /** {@code --light-multiple}: {@link HillshadeOptions}. */
    static final class LightMultiple implements ITypeConverter<Double> {
        @Override
        public Double convert(String text) {
            return checkedDouble(text, HillshadeOptions.DEFAULTS::withLightMultiple);
        }
    }

    /** {@code --light-intensity}: {@link HillshadeOptions}. */
    static final class LightIntensity implements ITypeConverter<Double> {
        @Override
        public Double convert(String text) {
            return checkedDouble(text, v -> HillshadeOptions.DEFAULTS.withIntensities(v,
                    HillshadeOptions.DEFAULTS.relativeDarkIntensity()));
        }
    }

    /** {@code --dark-intensity}: {@link HillshadeOptions}. */
    static final class DarkIntensity implements ITypeConverter<Double> {
        @Override
        public Double convert(String text) {
            return checkedDouble(text, v -> HillshadeOptions.DEFAULTS.withIntensities(
                    HillshadeOptions.DEFAULTS.relativeLightIntensity(), v));
        }
    }

    /** {@code --spot-exponent}: {@link HillshadeOptions}. */
    static final class SpotExponent implements ITypeConverter<Double> {
        @Override
        public Double convert(String text) {
            return checkedDouble(text, HillshadeOptions.DEFAULTS::withSpotExponent);
        }
    }

    /** {@code --xy-scale}: {@link HillshadeOptions}, where NaN means "not given", which the option cannot say. */
    static final class XyScale implements ITypeConverter<Double> {
        @Override
        public Double convert(String text) {
            return checkedDouble(text, v -> {
                if (Double.isNaN(v)) {
                    throw new IllegalArgumentException("the horizontal scale must be a finite number above 0, got"
                            + " NaN");
                }
                HillshadeOptions.DEFAULTS.withHorizontalScale(v);
            });
        }
    }

    /** {@code --sun-azimuth}: {@link LightDirection}. */
    static final class Azimuth implements ITypeConverter<Double> {
        @Override
        public Double convert(String text) {
            return checkedDouble(text, v -> new LightDirection(v, 25));
        }
    }

    /** {@code --sun-elevation}: {@link LightDirection}. */
    static final class Elevation implements ITypeConverter<Double> {
        @Override
        public Double convert(String text) {
            return checkedDouble(text, v -> new LightDirection(320, v));
        }
    }

    /** {@code --sun-time}: the text itself once {@link ZonedTimeParser} reads it. */
    static final class Time implements ITypeConverter<String> {
        @Override
        public String convert(String text) {
            checked(() -> ZonedTimeParser.parse(text));
            return text;
        }
    }

    /** {@code --shadow-intensity}: {@link Scene}. */
    static final class ShadowIntensity implements ITypeConverter<Double> {
        @Override
        public Double convert(String text) {
            return checkedDouble(text, Scene.defaults()::withShadowIntensity);
        }
    }

    /** {@code --ambient}: {@link Scene#withAmbient}. */
    static final class Ambient implements ITypeConverter<Double> {
        @Override
        public Double convert(String text) {
            return checkedDouble(text, Scene.defaults()::withAmbient);
        }
    }

    /** {@code --sky-directions}: {@link io.github.jdem846.shadow.SkyViewOptions}. */
    static final class SkyDirections implements ITypeConverter<Integer> {
        @Override
        public Integer convert(String text) {
            return checkedInt(text, Scene.defaults()::withSkyDirections);
        }
    }

    /** {@code --blend}: {@link io.github.jdem846.render.BlendMode}. */
    static final class BlendModeName implements ITypeConverter<io.github.jdem846.render.BlendMode> {
        @Override
        public io.github.jdem846.render.BlendMode convert(String text) {
            return checked(() -> io.github.jdem846.render.BlendMode.named(text));
        }
    }

    /** {@code --hillshade-opacity}: {@link io.github.jdem846.render.Blend}. */
    static final class HillshadeOpacity implements ITypeConverter<Double> {
        @Override
        public Double convert(String text) {
            return checkedDouble(text, io.github.jdem846.render.Blend.DEFAULT::withOpacity);
        }
    }

    /** {@code --sky-radius}: a finite positive number of metres ({@link io.github.jdem846.shadow.SkyViewOptions}). */
    static final class SkyRadius implements ITypeConverter<Double> {
        @Override
        public Double convert(String text) {
            return checkedDouble(text, r -> {
                if (!(r < Double.POSITIVE_INFINITY)) {
                    throw new IllegalArgumentException("the sky-view search radius must be a finite number of metres"
                            + " above 0 (leave the option out to search the whole grid), got " + text.trim());
                }
                Scene.defaults().withSkyRadius(r);
            });
        }
    }

    /** {@code --light-model}: {@link io.github.jdem846.render.LightModel}. */
    static final class LightModelName implements ITypeConverter<io.github.jdem846.render.LightModel> {
        @Override
        public io.github.jdem846.render.LightModel convert(String text) {
            return checked(() -> MethodNames.lightModel(text));
        }
    }

    /** {@code --refraction}: {@link ShadowOptions}. */
    static final class Refraction implements ITypeConverter<Double> {
        @Override
        public Double convert(String text) {
            return checkedDouble(text, k -> ShadowOptions.DEFAULTS.withEarthCurvature(true, k, Double.NaN));
        }
    }

    /** {@code --body}: {@link Body#named}. */
    static final class BodyName implements ITypeConverter<Body> {
        @Override
        public Body convert(String text) {
            return checked(() -> Body.named(text));
        }
    }

    /** {@code --radius}: {@link Body#sphere}. */
    static final class Radius implements ITypeConverter<Body> {
        @Override
        public Body convert(String text) {
            return Body.sphere(checkedDouble(text, Body::sphere));
        }
    }

    /** {@code --hillshade} of render: a {@link HillshadeMethod}, or null for {@code none}. */
    static final class HillshadeOrNone implements ITypeConverter<HillshadeMethod> {
        @Override
        public HillshadeMethod convert(String text) {
            if (text.trim().equalsIgnoreCase("none")) {
                return null;
            }
            try {
                return MethodNames.hillshade(text);
            } catch (IllegalArgumentException e) {
                throw new TypeConversionException(e.getMessage() + ", or none");
            }
        }
    }

    /** {@code --method} of hillshade: {@link MethodNames#hillshade}. */
    static final class Method implements ITypeConverter<HillshadeMethod> {
        @Override
        public HillshadeMethod convert(String text) {
            return checked(() -> MethodNames.hillshade(text));
        }
    }

    /** {@code --shadows} of render: {@link MethodNames#shadows}. */
    static final class Algorithm implements ITypeConverter<ShadowAlgorithm> {
        @Override
        public ShadowAlgorithm convert(String text) {
            return checked(() -> MethodNames.shadows(text));
        }
    }

    /** {@code --algorithm} of shadows: an algorithm that makes a mask (not {@code none}). */
    static final class MaskAlgorithm implements ITypeConverter<ShadowAlgorithm> {
        @Override
        public ShadowAlgorithm convert(String text) {
            ShadowAlgorithm a = checked(() -> MethodNames.shadows(text));
            if (a == ShadowAlgorithm.NONE) {
                throw new TypeConversionException("none makes no mask; choose sweep, march or exact");
            }
            return a;
        }
    }

    /** {@code --height} of sun: {@link Observer#atHeight}. */
    static final class ObserverHeight implements ITypeConverter<Double> {
        @Override
        public Double convert(String text) {
            return checkedDouble(text, Observer::atHeight);
        }
    }

    /** {@code --pressure}: {@link Observer}. */
    static final class Pressure implements ITypeConverter<Double> {
        @Override
        public Double convert(String text) {
            return checkedDouble(text, Observer.SEA_LEVEL::withPressure);
        }
    }

    /** {@code --temperature}: {@link Observer}. */
    static final class Temperature implements ITypeConverter<Double> {
        @Override
        public Double convert(String text) {
            return checkedDouble(text, Observer.SEA_LEVEL::withTemperature);
        }
    }

    /** {@code --delta-t}: {@link Observer}. */
    static final class DeltaT implements ITypeConverter<Double> {
        @Override
        public Double convert(String text) {
            return checkedDouble(text, Observer.SEA_LEVEL::withDeltaT);
        }
    }
}
