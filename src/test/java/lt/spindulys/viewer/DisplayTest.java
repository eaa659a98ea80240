package lt.spindulys.viewer;

import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.extension.ExtendWith;

/**
 * Marks a test that opens real windows and drives them with {@link java.awt.Robot}: it runs when
 * there is a display (an X server, such as the virtual one {@code .ci/run} starts) and is skipped
 * otherwise, with the reason ("no display: DISPLAY is not set"), which JUnit reports and
 * {@link DisplayCondition} also prints once on standard error so a console run shows it.
 */
@Target({ElementType.TYPE, ElementType.METHOD})
@Retention(RetentionPolicy.RUNTIME)
@ExtendWith(DisplayCondition.class)
@Tag("display")
public @interface DisplayTest {
}
